/* ssao_constants.h - constants and the uniform-block layout shared by the C++
 * plugin and every GLSL shader. The build prepends this file to each shader
 * after its #version line, so it must stay valid GLSL and valid C++: only
 * #define lines, comments, and the blocks below written with the SSAO_* type
 * macros. */
#ifndef SSAO_CONSTANTS_H
#define SSAO_CONSTANTS_H

#define SSAO_MAX_KERNEL 64          /* = SSAO_MAX_SAMPLES of the ABI */
#define SSAO_NOISE_SIZE 4           /* the noise texture is 4x4 */
#define SSAO_BLUR_MAX_TAPS 16       /* = SSAO_MAX_BLUR_RADIUS of the ABI */
#define SSAO_MARCH_MAX_STEPS 32     /* = SSAO_MAX_STEPS of the ABI */
/* A march of N steps with jitter u in [0, 1) places step j at
 * (j + u) R / (N - SSAO_MARCH_STRETCH (1 - u)): the last step lands between
 * (N - 1) / (N - SSAO_MARCH_STRETCH) R and R (visibility.frag says why). */
#define SSAO_MARCH_STRETCH 0.5
/* The depth tests against a tangent plane (the blur's, the upsample's) accept
 * this share of the blur's relative depth tolerance (ao_texture.glsl). */
#define SSAO_PLANE_TOLERANCE 0.2
/* The depth-aware blur's line and the upsample's plane fit (blur.frag,
 * upsample.frag) add this to the taps' offset variance (squared pass or grid
 * texels) to damp the slope. */
#define SSAO_BLUR_SLOPE_DAMPING 0.25
/* The view z that marks the sky (and a depth whose position is not finite)
 * in the grid's plane texels and the AO texture (common.glsl SKY_Z); the
 * runner clears a sky-tested pass's target to it (runner.cpp). */
#define SSAO_SKY_Z 3.0e38

/* Texture units the passes sample from (the state guard saves exactly these). */
#define SSAO_UNIT_DEPTH 0
#define SSAO_UNIT_NORMAL 1
#define SSAO_UNIT_NOISE 2
#define SSAO_UNIT_AO 3
#define SSAO_UNITS_USED 4

/* Uniform-buffer binding points. */
#define SSAO_UBO_FRAME 0
#define SSAO_UBO_KERNEL 1

/* Enum values the shaders branch on; static_asserted equal to the ABI's. */
#define SSAO_SHADER_KERNEL_HEMISPHERE 1
#define SSAO_SHADER_KERNEL_SPHERE 2
#define SSAO_SHADER_KERNEL_SEPARABLE 3
#define SSAO_SHADER_ROTATION_NOISE 1
#define SSAO_SHADER_ROTATION_HASH 2
#define SSAO_SHADER_ROTATION_NONE 3
#define SSAO_SHADER_ROTATION_GRADIENT_NOISE 4
#define SSAO_SHADER_NORMAL_VIEW 1
#define SSAO_SHADER_NORMAL_WORLD 2
#define SSAO_SHADER_PACKING_UNORM 1
#define SSAO_SHADER_PACKING_SIGNED 2
#define SSAO_SHADER_BLUR_DEPTH_AWARE 1
#define SSAO_SHADER_BLUR_BOX 2
#define SSAO_SHADER_BLUR_GAUSSIAN 3
#define SSAO_SHADER_METHOD_KERNEL 1
#define SSAO_SHADER_METHOD_VISIBILITY 2

#ifdef __cplusplus
#  define SSAO_BLOCK(name) struct alignas(16) name
#  define SSAO_BLOCK_END(instance) ;
#  define SSAO_MAT4 ssao_std140::mat4
#  define SSAO_VEC4 ssao_std140::vec4
#  define SSAO_VEC2 ssao_std140::vec2
#  define SSAO_IVEC2 ssao_std140::ivec2
#  define SSAO_FLOAT float
#  define SSAO_INT int32_t
#else
#  define SSAO_BLOCK(name) layout(std140) uniform name
#  define SSAO_BLOCK_END(instance) instance;
#  define SSAO_MAT4 mat4
#  define SSAO_VEC4 vec4
#  define SSAO_VEC2 vec2
#  define SSAO_IVEC2 ivec2
#  define SSAO_FLOAT float
#  define SSAO_INT int
#endif

/* Per-frame constants, derived on the CPU from the viewport, the projection
 * and the settings (plugin/constants.cpp make_frame_block). GLSL reads them
 * as consts.NAME, C++ as SsaoFrame::NAME. std140: the byte offset of every
 * member is in its comment and static_asserted in plugin/uniforms.h; the
 * padding is written out so that no member moves silently. Flags are ints
 * (0 or 1); the enum members hold the SSAO_SHADER_* values above. */
SSAO_BLOCK(SsaoFrame) {
    SSAO_MAT4 proj;              /*   0: view -> clip */
    SSAO_MAT4 inv_proj;          /*  64: clip -> view (computed in double, stored as float) */
    SSAO_MAT4 normal_to_view;    /* 128: world -> view rotation for world-space normals (identity else) */
    SSAO_IVEC2 viewport_origin;  /* 192: x, y of the viewport in the input textures */
    SSAO_IVEC2 viewport_size;    /* 200: its width, height */
    SSAO_INT sample_count;       /* 208: kernel samples, or visibility directions */
    SSAO_INT step_count;         /* 212: visibility: steps per direction */
    SSAO_INT seed;               /* 216: the rotation hash's seed */
    SSAO_INT rotation;           /* 220: SSAO_SHADER_ROTATION_* */
    SSAO_INT normal_space;       /* 224: SSAO_SHADER_NORMAL_* */
    SSAO_INT normal_packing;     /* 228: SSAO_SHADER_PACKING_* */
    SSAO_INT blur_radius;        /* 232: gaussian taps either side of the centre */
    SSAO_INT blur_kind;          /* 236: SSAO_SHADER_BLUR_* */
    SSAO_INT orthographic;       /* 240: flag: an orthographic projection */
    SSAO_INT frame_pick_swap;    /* 244: variant FRAME_NOISE: 1 in the frames whose grid picks the other diagonal corner */
    SSAO_FLOAT ndc_per_depth;    /* 248: d(ndc z)/d(depth): 2 for the [-1,1] clip range, 1 for [0,1] */
    SSAO_FLOAT sky_depth;        /* 252: the depth value of the far plane (cleared depth) */
    SSAO_FLOAT unorm_depth_step; /* 256: one step of a unorm depth format; 0 for a float format */
    SSAO_FLOAT radius;           /* 260: sampling radius (view units) */
    SSAO_FLOAT bias;             /* 264: constant depth bias (view units, scales with the radius) */
    SSAO_FLOAT depth_step_bias;  /* 268: bias in steps of the depth format */
    SSAO_FLOAT strength;         /* 272: occlusion scale before the power */
    SSAO_FLOAT power;            /* 276: exponent of the AO */
    SSAO_FLOAT thickness;        /* 280: visibility: the depth a surface is taken to have (view units) */
    SSAO_FLOAT blur_sigma;       /* 284: gaussian sigma (texels) */
    SSAO_FLOAT blur_depth_tolerance; /* 288: relative view-z difference at which a tap gets no weight */
    SSAO_FLOAT fade_start;       /* 292: variant FADE: view depth where the fade begins */
    SSAO_FLOAT fade_end;         /* 296: ... and where AO is 1 */
    SSAO_FLOAT radius_pixels;    /* 300: variant RADIUS_PIXELS: the radius in viewport pixels */
    SSAO_VEC2 frame_rotation;    /* 304: variant FRAME_NOISE: cos, sin of the frame's rotation offset */
    SSAO_FLOAT frame_step_offset;/* 312: variant FRAME_NOISE: the frame's step-jitter offset in [0,1) */
    SSAO_FLOAT max_step_texels;  /* 316: visibility: the longest step on screen, sampling-grid texels */
    /* View xy from view z (plugin/projection.h ViewFromZ):
     * xy = (mul_z px + add_z) z + (mul_1 px + add_1) for viewport pixel coordinates px. */
    SSAO_VEC4 view_mul_z;        /* 320: mat2 mul_z, column-major */
    SSAO_VEC4 view_mul_1;        /* 336: mat2 mul_1, column-major */
    SSAO_VEC2 view_add_z;        /* 352 */
    SSAO_VEC2 view_add_1;        /* 360 */
    /* Clip w and z from view z: w = clip_w_z z + clip_w_1, z = clip_z_z z + clip_z_1. */
    SSAO_FLOAT clip_w_z;         /* 368 */
    SSAO_FLOAT clip_w_1;         /* 372 */
    SSAO_FLOAT clip_z_z;         /* 376 */
    SSAO_FLOAT clip_z_1;         /* 380 */
    SSAO_FLOAT inv_det;          /* 384: 1 / |clip_z_z clip_w_1 - clip_z_1 clip_w_z|:
                                    d(view z)/d(ndc z) = w^2 inv_det */
    SSAO_FLOAT pad1;             /* 388 */
    SSAO_FLOAT pad2;             /* 392 */
    SSAO_FLOAT pad3;             /* 396; size 400 */
}
SSAO_BLOCK_END(consts)

/* The kernel's sample points (or, for the visibility method, the unit
 * directions), in tangent space (z along the normal), xyz per vec4. GLSL
 * reads kernel.vectors[i]. */
SSAO_BLOCK(SsaoKernel) {
    SSAO_VEC4 vectors[SSAO_MAX_KERNEL]; /* 0, stride 16 */
}
SSAO_BLOCK_END(kernel)

#endif
