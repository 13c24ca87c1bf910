// crease_textures.h - the crease scene's G-buffer (size x size, 60-degree
// perspective, GL clip range) as textures on the fixture's (current) context,
// and the inputs that hand them to the library.
#pragma once

#include "gl_fixture.h"
#include "test_scenes.h"

namespace testscenes {

struct CreaseTextures {
    glm::dmat4 proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    analytic::GBuffer g;
    GLuint depth = 0, normal = 0;
    ssao_inputs in{};
    explicit CreaseTextures(testgl::Fixture& fx, int size = 32)
        : g(analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, size, size)) {
        const testgl::Textures t = fx.upload(g);
        depth = t.depth;
        normal = t.normal;
        in = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    }
};

}  // namespace testscenes
