/* ssao_constants.h - constants and the uniform-block layout shared by the C++
 * plugin and every GLSL shader. The build prepends this file to each shader
 * after its #version line, so it must stay valid GLSL and valid C++: only
 * #define lines, comments, and the block below written with the SSAO_* type
 * macros. */
#ifndef SSAO_CONSTANTS_H
#define SSAO_CONSTANTS_H

#define SSAO_MAX_KERNEL 64          /* = SSAO_MAX_SAMPLES of the ABI */
#define SSAO_NOISE_SIZE 4           /* the noise texture is 4x4 */
#define SSAO_BLUR_MAX_TAPS 16       /* = SSAO_MAX_BLUR_RADIUS of the ABI */

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
#  define SSAO_MAT4 ssao_std140::mat4
#  define SSAO_VEC4 ssao_std140::vec4
#  define SSAO_IVEC4 ssao_std140::ivec4
#  define SSAO_BLOCK_END ;
#else
#  define SSAO_BLOCK(name) layout(std140) uniform name
#  define SSAO_MAT4 mat4
#  define SSAO_VEC4 vec4
#  define SSAO_IVEC4 ivec4
#  define SSAO_BLOCK_END ;
#endif

/* Per-frame constants, derived on the CPU from the viewport, the projection
 * and the settings (std140: every member is 16-byte aligned). */
SSAO_BLOCK(SsaoFrame) {
    SSAO_MAT4 u_proj;          /* view -> clip */
    SSAO_MAT4 u_inv_proj;      /* clip -> view (computed in double, stored as float) */
    SSAO_MAT4 u_normal_to_view;/* world -> view rotation for world-space normals (identity else) */
    SSAO_IVEC4 u_viewport;     /* x, y, w, h of the inputs */
    SSAO_IVEC4 u_method;       /* method (1 kernel, 2 visibility), steps per direction, 0, 0 */
    SSAO_IVEC4 u_modes;        /* kernel shape (informative: the kernel itself carries it), rotation,
                                  normal space, normal packing */
    SSAO_IVEC4 u_counts;       /* sample count, seed, blur radius, blur kind */
    SSAO_VEC4 u_ao;            /* radius, bias, depth-step bias, strength */
    SSAO_VEC4 u_ao2;           /* power, blur sigma, blur depth tolerance, ndc-per-depth (1 or 2) */
    SSAO_VEC4 u_depth;         /* far-plane depth value (sky), depth step of a unorm format (0 = float), reverse-Z, orthographic */
    SSAO_VEC4 u_march;         /* visibility: thickness (view units), 0, 0, 0 */
    SSAO_VEC4 u_fade;          /* (1.2) fade_start, fade_end (view depth), radius_pixels, 0: read only by
                                  the variants FADE and RADIUS_PIXELS */
    SSAO_VEC4 u_frame;         /* (1.2) variant FRAME_NOISE: cos and sin of frame_index's rotation offset,
                                  its step-jitter offset in [0,1), 0 */
    SSAO_VEC4 u_vz_mul_z;      /* view xy from view z (plugin/projection.h ViewFromZ): mat2 mul_z, column-major */
    SSAO_VEC4 u_vz_mul_1;      /* mat2 mul_1, column-major */
    SSAO_VEC4 u_vz_add;        /* add_z.xy, add_1.xy: xy = (mul_z px + add_z) z + (mul_1 px + add_1) */
    SSAO_VEC4 u_z_clip;        /* clip w = x * z + y, clip z = z * z + w (the depth step from view z) */
    SSAO_VEC4 u_z_det;         /* 1 / |z_z w_1 - z_1 w_z| (d(view z)/d(ndc z) = w^2 times it),
                                  1 when clip z has view x or y terms (oblique near plane) else 0, 0, 0 */
}
SSAO_BLOCK_END

/* The kernel (or, for the visibility method, the unit directions), in tangent
 * space (z along the normal), xyz per vec4. */
SSAO_BLOCK(SsaoKernel) {
    SSAO_VEC4 u_kernel[SSAO_MAX_KERNEL];
}
SSAO_BLOCK_END

#endif
