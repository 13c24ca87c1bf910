// crease_textures.h - the crease scene's G-buffer as textures on the fixture's
// (current) context, and the inputs that hand them to the library.
#pragma once

#include "gl_fixture.h"
#include "test_scenes.h"

namespace testscenes {

struct CreaseTextures {
    GLuint depth = 0, normal = 0;
    ssao_inputs in{};
    CreaseTextures(testgl::Fixture& fx, int size) {
        const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
        const analytic::GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, size, size);
        depth = fx.make_depth(GL_DEPTH_COMPONENT32F, size, size, g.depth);
        normal = fx.make_normals(GL_RGBA16F, size, size, g.normal);
        in = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    }
};

}  // namespace testscenes
