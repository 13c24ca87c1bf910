/**
 * @file ssao.h
 * The whole public C ABI of the SSAO plugin (libssao.so).
 *
 * Compiles as C99 and as C++. A host that dlopens the library needs exactly one
 * dlsym: "ssao_get_api" negotiates the interface version and fills a table of
 * function pointers. Nothing else is exported.
 *
 * @code
 *   void* lib = dlopen("libssao.so.1", RTLD_NOW | RTLD_LOCAL);
 *   PFN_ssao_get_api get_api = (PFN_ssao_get_api)dlsym(lib, "ssao_get_api");
 *   ssao_api api = {0};                     // {0}: in C, no -Wmissing-field-initializers
 *   api.size = sizeof(api);
 *   if (get_api(SSAO_API_VERSION, &api) != SSAO_OK) { ... }
 *   ssao_context_desc desc = {0};
 *   desc.size = sizeof(desc);
 *   desc.get_proc_address = my_get_proc;   // eglGetProcAddress, glfwGetProcAddress, ...
 *   ssao_context* ctx = NULL;
 *   api.create_context(&desc, &ctx);        // GL context current on this thread
 *   ...each frame: api.execute(ctx, &inputs, &output);
 *   api.destroy_context(ctx);               // same GL context current
 * @endcode
 *
 * Conventions
 * - Every struct begins with `uint32_t size`, which the caller sets to
 *   sizeof(the struct) as compiled against this header. Future versions only
 *   append fields; the library accepts the sizes of every version it knows and
 *   rejects any other with SSAO_ERROR_STRUCT_SIZE.
 * - A zero field means "the default" (see each field); resolve_settings and
 *   get_settings return the resolved values, never a zero that means default.
 * - Matrices are column-major float[16], the layout glUniformMatrix4fv takes
 *   with transpose = GL_FALSE (element [col*4 + row]).
 * - Functions return an ssao_status. No function aborts, throws or prints;
 *   when a context is given, ssao_api.last_error(ctx) holds a sentence on the
 *   most recent failure of that context. A failing call changes nothing (no
 *   settings applied, no GL state changed, no output written), with one
 *   exception: destroy_context always frees the context, even when it returns
 *   SSAO_ERROR_WRONG_CONTEXT; never call it twice on the same context.
 *
 * Threading and lifetime
 * - A context belongs to the one GL context that was current at
 *   create_context: not to its share group, since the vertex array,
 *   framebuffer and query objects it keeps are not shared between GL
 *   contexts. execute, get_timings and destroy_context must be made on a
 *   thread where that GL context is current; on any other (one sharing
 *   objects with it included, or none) they return SSAO_ERROR_WRONG_CONTEXT
 *   and touch nothing in GL. To use the library on two GL contexts, create
 *   one ssao_context on each. A context is not thread-safe; distinct
 *   contexts may be used from distinct threads with their own GL contexts.
 * - How the current context is recognised: at creation the library makes
 *   its vertex array exist and, with KHR_debug, labels it with a name unique
 *   in the process ("ssao: vertex array <n>"); each of those calls first asks
 *   glIsVertexArray and glGetObjectLabel (queries that raise no GL error).
 *   Without KHR_debug only glIsVertexArray is asked, so a foreign context
 *   that happens to hold a vertex array of the same name is not told apart.
 * - Textures passed to execute are only read (depth, normal) or rendered into
 *   (output) during that call; the library keeps no reference to them.
 * - The texture returned for plugin-owned output stays valid until the next
 *   execute that changes the viewport size or output format, or destroy_context.
 *   If the host deletes it, the next execute notices (glIsTexture, and with
 *   KHR_debug its "ssao: output <n>" label, n unique to the ssao_context, so
 *   a host texture or another context's output that reused the name is left
 *   alone) and makes a new one; destroy_context then deletes
 *   only a texture that is still the library's.
 * - destroy_context deletes every GL object the library made; call it while
 *   the GL context is still current (after that context is gone it only
 *   frees the library's memory, see destroy_context). ssao_get_api, status_string,
 *   resolve_settings and preset_settings need no GL context.
 *
 * GL state
 * - execute saves and restores, in one guard, every piece of GL state it
 *   changes: draw and read framebuffer bindings, current program, vertex array
 *   binding, active texture unit and the 2D texture, (1.2) 2D multisample
 *   texture and sampler bindings of every unit it uses (units
 *   0..SSAO_TEXTURE_UNITS_USED-1), array, uniform and
 *   pixel-unpack buffer bindings (and the indexed uniform bindings 0 and 1),
 *   viewport and scissor box (every index of a viewport array: GL 4.1 or
 *   GL_ARB_viewport_array), enables
 *   (scissor, depth, stencil, blend per draw buffer, cull face, rasterizer
 *   discard, polygon offset, colour logic op, sample mask, dither, framebuffer
 *   sRGB, multisample, alpha-to-coverage, clip distances 0-7), (1.2) the blend
 *   function and equation of draw buffer 0 (all buffers' below GL 4.0
 *   without GL_ARB_draw_buffers_blend) where
 *   the output is multiplied in, polygon mode,
 *   colour/depth/stencil write masks, the depth function and depth range
 *   (every index of a viewport array), clip control (where supported), the
 *   depth-stencil texture mode of a D24S8/D32FS8 input (GL 4.3+) and the
 *   unpack pixel-store parameters.
 * - Where query buffers exist (GL 4.4 or ARB_query_buffer_object), a buffer
 *   bound to GL_QUERY_BUFFER would make reading the timer queries write into
 *   it: execute and get_timings unbind it while they read them and bind it
 *   back. No other buffer binding matters to it: it reads no pixels back
 *   (pixel-pack), draws no indirect or indexed draws (draw-indirect; the
 *   element array belongs to its own vertex array) and uses no copy-read/
 *   write, texture, atomic-counter, shader-storage, dispatch-indirect or
 *   transform-feedback buffer: those bindings are neither read nor changed.
 * - It assumes, and does not save: the texture parameters of the host's
 *   textures other than the depth-stencil mode (it reads them with texelFetch
 *   through its own sampler objects, so filters, wrap and compare modes do not
 *   matter; base level 0 and no swizzle are assumed); that no transform
 *   feedback, conditional render or occlusion/primitive query is active (GL
 *   would refuse, skip or count its draws); that the depth range lies in
 *   [0, 1] (one set unclamped through GL_NV_depth_buffer_float comes back
 *   clamped). A current program the host already
 *   flagged for deletion is deleted when execute binds its own; the guard then
 *   leaves program 0 current. It does the same for a current program whose
 *   last re-link failed: GL keeps its old executable in use until another
 *   program is made current, and refuses to make it current again. It never
 *   calls glGetError (so the host's pending errors stay the host's, and a GL
 *   allocation failure cannot be reported as OUT_OF_MEMORY).
 * - Below GL 4.5 a texture name of another target (a 2D array, say) cannot be
 *   told from a 2D texture without binding it: the failed bind raises
 *   GL_INVALID_OPERATION, which the host's debug output will see, and execute
 *   returns SSAO_ERROR_INVALID_TEXTURE. (1.2) An input is tried as
 *   GL_TEXTURE_2D and as GL_TEXTURE_2D_MULTISAMPLE, the target the previous
 *   successful execute's inputs had first: a name of neither raises two
 *   errors, and a host whose inputs change between the two targets one per
 *   change.
 * - Requirements: a GL 3.3 core context or newer. Clip control (4.5 or
 *   ARB_clip_control), timer queries and GL_TEXTURE_TARGET queries (4.5) are
 *   used when present.
 * - Debug names: with KHR_debug (GL 4.3 or the extension) execute wraps its
 *   work in the debug group "ssao" and each pass in its own ("ssao: grid",
 *   "ssao: kernel", ...: see ssao_pass);
 *   pushes and pops are balanced on every return, so the debug-group stack
 *   depth is unchanged, and no group is pushed when the stack has no room for
 *   two more. The library's GL objects carry glObjectLabel names "ssao: ...".
 *   The host sees the group messages in its debug callback (type
 *   GL_DEBUG_TYPE_PUSH_GROUP / POP_GROUP, source APPLICATION). Without
 *   KHR_debug nothing of this is called.
 */
#ifndef SSAO_SSAO_H
#define SSAO_SSAO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The calling convention of every function of the ABI (cdecl on Windows). */
#if defined(_WIN32)
#  define SSAO_CALL __cdecl
#else
#  define SSAO_CALL
#endif

/** Interface version: major in the high 16 bits, minor in the low 16 bits.
 * A host asking for major M gets any library of major M with minor >= its
 * own minor; the table's `version` field says which one it got. */
#define SSAO_MAKE_VERSION(major, minor) ((uint32_t)(((major) << 16) | (minor)))
/** The interface this header declares: pass it to ssao_get_api. */
#define SSAO_API_VERSION SSAO_MAKE_VERSION(1, 4)
/** The major part of an interface version. */
#define SSAO_VERSION_MAJOR(v) ((uint32_t)(v) >> 16)
/** The minor part of an interface version. */
#define SSAO_VERSION_MINOR(v) ((uint32_t)(v) & 0xffffu)

/* Limits, also read by the shaders (see shaders/ssao_constants.h). */
#define SSAO_MAX_SAMPLES 64        /**< most kernel samples or visibility directions (sample_count) */
#define SSAO_MAX_BLUR_RADIUS 16    /**< most blur taps either side (blur_radius) */
#define SSAO_MAX_STEPS 32          /**< most steps per visibility direction (step_count) */
#define SSAO_MAX_DIMENSION 16384   /**< largest viewport width or height, pixels */
#define SSAO_TEXTURE_UNITS_USED 4  /**< texture units 0..3 are bound during execute (and restored) */
#define SSAO_MAX_PASSES 8          /**< passes of one execute: room in ssao_timings (1.1) */
#define SSAO_MAX_POWER 16.0f       /**< largest power */
#define SSAO_MAX_STRENGTH 8.0f     /**< largest strength */
#define SSAO_MAX_BLUR_SIGMA 64.0f  /**< largest blur_sigma, pixels */
#define SSAO_MAX_DEPTH_STEP_BIAS 1e6f  /**< largest depth_step_bias */
#define SSAO_MAX_STEP_TEXELS 1e6f  /**< largest max_step_texels (1.4) */

/* ---------------------------------------------------------------- status */
/** What every function returns: SSAO_OK or why it refused (status_string gives a sentence). */
typedef enum ssao_status {
    SSAO_OK = 0,                /**< success */
    /** A required pointer argument was NULL. Remedy: pass a valid pointer. */
    SSAO_ERROR_NULL_POINTER = 1,
    /** A struct's `size` field matches no version of that struct this library
     * knows. Remedy: set size = sizeof(struct) from the header you compile with. */
    SSAO_ERROR_STRUCT_SIZE = 2,
    /** ssao_get_api: the requested major version is not this library's, or its
     * minor is newer than this library's. Remedy: use a matching library. */
    SSAO_ERROR_VERSION_MISMATCH = 3,
    /** An enum field holds a value outside its documented list. */
    SSAO_ERROR_INVALID_ENUM = 4,
    /** A number is non-finite (NaN, inf) or outside its documented range. */
    SSAO_ERROR_INVALID_VALUE = 5,
    /** A size is zero, negative, larger than SSAO_MAX_DIMENSION, or the
     * viewport does not lie inside the input textures. */
    SSAO_ERROR_INVALID_SIZE = 6,
    /** A texture name is 0 where one is required, is not a texture, is not a
     * GL_TEXTURE_2D ((1.2) the depth and normal textures may both be
     * GL_TEXTURE_2D_MULTISAMPLE), the depth and normal textures differ in
     * size, target or sample count, or the output (the host's output_texture,
     * or without one the library's own) is also an input. */
    SSAO_ERROR_INVALID_TEXTURE = 7,
    /** The depth texture's internal format is not D16, D24, D24S8, D32F or
     * D32FS8, the normal texture has fewer than three channels or an integer
     * format, or the output texture is not colour-renderable. */
    SSAO_ERROR_UNSUPPORTED_FORMAT = 8,
    /** The projection matrix is singular or not a projection (for example all
     * zeros, or w does not depend on view z the way a perspective or an
     * orthographic projection does). */
    SSAO_ERROR_INVALID_PROJECTION = 9,
    /** create_context: the current GL context is older than 3.3 core, or no
     * GL context is current (glGetString returned NULL). */
    SSAO_ERROR_GL_VERSION = 10,
    /** create_context: get_proc_address returned NULL for a GL 3.3 function. */
    SSAO_ERROR_GL_LOAD = 11,
    /** A shader failed to compile or link on this driver; last_error holds
     * the driver's log. Should not happen on a conformant driver: report it. */
    SSAO_ERROR_SHADER = 12,
    /** An internal framebuffer is incomplete (for example the output texture's
     * format cannot be rendered to on this driver). */
    SSAO_ERROR_FRAMEBUFFER = 13,
    /** Memory could not be allocated. */
    SSAO_ERROR_OUT_OF_MEMORY = 14,
    /** A bug in the library; last_error says where. */
    SSAO_ERROR_INTERNAL = 15,
    /** The GL context current on this thread is not the one the context
     * was created on (another context, one sharing objects with it, or none:
     * the creating one was destroyed). Nothing was done in GL. Remedy: make
     * the creating GL context current (see "Threading and lifetime"). */
    SSAO_ERROR_WRONG_CONTEXT = 16,
    SSAO_STATUS_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_status;

/* --------------------------------------------------------------- settings */
/** The volume the kernel method samples (settings.kernel_shape). */
typedef enum ssao_kernel_shape {
    SSAO_KERNEL_DEFAULT = 0,      /**< = SSAO_KERNEL_HEMISPHERE */
    SSAO_KERNEL_HEMISPHERE = 1,   /**< normal-oriented hemisphere (the chapter's) */
    SSAO_KERNEL_SPHERE = 2,       /**< full sphere, normals only rotate it (Crytek look: flat = 0.5) */
    SSAO_KERNEL_SEPARABLE = 3, /**< two tangent planes (x-z and y-z), half the samples each (student report) */
    SSAO_KERNEL_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_kernel_shape;

/** How the kernel method spreads its samples along the radius (settings.distribution). */
typedef enum ssao_kernel_distribution {
    SSAO_DISTRIBUTION_DEFAULT = 0,      /**< = SSAO_DISTRIBUTION_ACCELERATING */
    SSAO_DISTRIBUTION_ACCELERATING = 1, /**< length scaled by lerp(0.1, 1, (i/N)^2): denser near the centre */
    SSAO_DISTRIBUTION_UNIFORM = 2, /**< uniform in the (hemi)sphere's volume */
    SSAO_DISTRIBUTION_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_kernel_distribution;

/** How the kernel or the directions turn from pixel to pixel (settings.rotation). */
typedef enum ssao_rotation {
    SSAO_ROTATION_DEFAULT = 0,  /**< the method's: GRADIENT_NOISE for VISIBILITY, NOISE_4X4 for KERNEL */
    SSAO_ROTATION_NOISE_4X4 = 1,/**< 4x4 tiled noise texture, tiled per viewport pixel (the chapter's, which
                                     its 4x4 box blur averages out); below full resolution GRADIENT_NOISE,
                                     since a tile there would repeat every 4 grid texels */
    SSAO_ROTATION_HASH = 2,     /**< per-pixel hash of the pixel position and seed */
    SSAO_ROTATION_NONE = 3, /**< no rotation: every pixel uses the same kernel (banding) */
    SSAO_ROTATION_GRADIENT_NOISE = 4, /**< (1.3) interleaved gradient noise on the sampling grid: no period,
                                     and each small neighbourhood spreads its angles and step offsets
                                     evenly, which a blur or the upsample then averages */
    SSAO_ROTATION_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_rotation;

/** The filter after the sampling pass (settings.blur). */
typedef enum ssao_blur {
    SSAO_BLUR_DEFAULT = 0,      /**< = SSAO_BLUR_DEPTH_AWARE */
    SSAO_BLUR_DEPTH_AWARE = 1,  /**< separable gaussian whose taps beyond blur_depth_tolerance are dropped;
                                     a line fitted through the rest, read at the centre */
    SSAO_BLUR_BOX_4X4 = 2,      /**< the chapter's 4x4 box (offsets -2..1); ignores depth at full
                                     resolution (below it, taps are weighed by depth as DEPTH_AWARE's) */
    SSAO_BLUR_GAUSSIAN = 3,     /**< separable gaussian of blur_sigma over blur_radius; ignores depth at
                                     full resolution (below it, as BOX_4X4) */
    SSAO_BLUR_NONE = 4, /**< no blur pass runs */
    SSAO_BLUR_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_blur;

/** How occlusion is estimated (settings.method). */
typedef enum ssao_method {
    SSAO_METHOD_DEFAULT = 0,      /**< the DEFAULT preset's (visibility) */
    SSAO_METHOD_KERNEL = 1,       /**< the chapter's point kernel: the fraction of kernel points behind
                                     the depth buffer (a volume estimate, range-checked); uses
                                     kernel_shape and distribution */
    SSAO_METHOD_VISIBILITY = 2,   /**< ray-marched visibility: sample_count cosine-weighted directions,
                                     each marched to radius in step_count jittered steps (more where
                                     a step would exceed max_step_texels on screen, if set); a step is
                                     blocked when it lies behind the depth buffer by less than
                                     thickness, or further behind a surface that the segment from the
                                     previous step crossed. Converges to the cosine-weighted open fraction of the
                                     hemisphere that one depth layer can show (docs/benchmark.md, "Estimators") */
    SSAO_METHOD_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_method;

/** At which resolution the sampling pass runs (settings.resolution). Below full
 * resolution the grid pass picks one real texel of each 2x2 (4x4) block of
 * the viewport (never an average of depths), the sampling pass and the blur
 * run on that grid, and a depth-aware upsample writes every viewport pixel
 * (docs/api.md, "Half resolution"). */
typedef enum ssao_resolution {
    SSAO_RESOLUTION_DEFAULT = 0,  /**< the method's default: the DEFAULT preset's (half) for its method */
    SSAO_RESOLUTION_FULL = 1,     /**< one AO sample per viewport pixel */
    SSAO_RESOLUTION_HALF = 2,     /**< one per 2x2 block: ceil(w/2) x ceil(h/2) */
    SSAO_RESOLUTION_QUARTER = 3,  /**< one per 4x4 block: ceil(w/4) x ceil(h/4) */
    SSAO_RESOLUTION_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_resolution;

/** The format of the library's own output texture (settings.output_format). */
typedef enum ssao_output_format {
    SSAO_OUTPUT_DEFAULT = 0,    /**< = SSAO_OUTPUT_R8 */
    SSAO_OUTPUT_R8 = 1,         /**< GL_R8 */
    SSAO_OUTPUT_R16F = 2,       /**< GL_R16F */
    SSAO_OUTPUT_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_output_format;

/** (1.2) What execute writes into the output instead of the AO (settings.debug_view):
 * the anchors' debug modes, for looking at what the pass sees. The normal views
 * write the view-space normal packed as n * 0.5 + 0.5 into red, green and blue;
 * the library's own output is then RGBA8 (output_format is ignored). A host
 * texture needs three channels for them (else UNSUPPORTED_FORMAT); sky
 * pixels have no normal and read (0.5, 0.5, 0.5). A view overwrites the output
 * rectangle whatever inputs.output_mode says: in MULTIPLY mode it replaces
 * the host's lit image there (RGB = the view, alpha = 1), so the view is what
 * the host shows. */
typedef enum ssao_debug_view {
    SSAO_DEBUG_VIEW_NONE = 0,         /**< the AO (default) */
    SSAO_DEBUG_VIEW_NORMALS = 1,      /**< the normals the sampling pass reads (the G-buffer's, rotated and
                                         unpacked; or the reconstructed ones when normal_texture is 0) */
    SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS = 2, /**< the normals rebuilt from depth alone, whatever the inputs */
    SSAO_DEBUG_VIEW_RAW_AO = 3,       /**< the sampling pass's AO before any blur (upsampled without depth
                                         weights below full resolution) */
    SSAO_DEBUG_VIEW_BLUR_WEIGHTS = 4, /**< the share of the blur's gaussian weight that passed the depth test
                                         (1 = nothing rejected; separable blurs: the product of both
                                         passes' shares); 1 everywhere for BOX_4X4 and GAUSSIAN at full
                                         resolution and without a blur */
    SSAO_DEBUG_VIEW_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_debug_view;

/** strength is a multiplier in which 0 is meaningful (no AO at all). Because a
 * zero field means "default", ask for strength 0 with this value. */
#define SSAO_STRENGTH_OFF (-1.0f)

/** What the pass computes and how: every field 0 means its default
 * (resolve_settings shows the values a zero becomes). */
typedef struct ssao_settings {
    uint32_t size;               /**< sizeof(ssao_settings) */
    uint32_t sample_count;       /**< kernel samples or visibility directions, 1..64. Defaults of the
                                    fields a preset sets (sample_count, distribution, blur, method,
                                    step_count, resolution): the DEFAULT preset's; with only the
                                    method set to the other estimator, that estimator's classic
                                    configuration (kernel: the LearnOpenGL chapter's 64 accelerating
                                    samples with the 4x4 box blur, full resolution; visibility: 8
                                    directions x 8 steps, depth-aware blur, full resolution) */
    float radius;                /**< sampling radius, view-space units, > 0; default 0.5 */
    float bias;                  /**< depth bias, view-space units, > 0; default 0.025 * radius
                                    (kernel method) or 0.0025 * radius (visibility method)
                                    (for no constant bias give a tiny value such as 1e-30).
                                    A bias proportional to the depth buffer's step at each
                                    pixel (depth_step_bias) is always added. */
    float depth_step_bias;       /**< multiple of the depth format's step at the pixel's depth
                                    (visibility: plus as many where that step is largest
                                    among the surfaces a step can meet), (0, 1e6]; default 2 */
    float power;                 /**< exponent applied to the result, [FLT_MIN, 16]; default 1 */
    float strength;              /**< occlusion multiplier, [0, 8]; default 1.
                                    ao = pow(1 - strength * occlusion, power), clamped to [0,1].
                                    SSAO_STRENGTH_OFF: strength 0, output is 1 and no pass samples. */
    ssao_kernel_shape kernel_shape;             /**< default hemisphere */
    ssao_kernel_distribution distribution;      /**< kernel only; default: see sample_count */
    ssao_rotation rotation;                     /**< default: the method's (visibility: gradient noise,
                                                     kernel: 4x4 noise) */
    uint32_t seed;               /**< seed of kernel, noise and hash; 0 = default seed 1 (deterministic) */
    ssao_blur blur;                             /**< default: see sample_count */
    uint32_t blur_radius;        /**< taps either side, pixels, 1..16; default 2 (box 4x4 ignores it) */
    float blur_sigma;            /**< gaussian sigma, pixels, (0, 64]; default blur_radius (gaussian and depth-aware) */
    float blur_depth_tolerance;  /**< depth-aware blur: a tap counts when |z_tap - z_centre| <=
                                    tolerance * |z_centre| (relative view depth), (0, 1]; default 0.05.
                                    Where the centre has a tangent plane (its normal not along the view
                                    axis) the blur uses 0.2 * tolerance against the depth that plane puts
                                    under the tap (at full resolution plus the miss of the tap's own plane
                                    under the centre), and the upsample below full resolution
                                    0.2 * tolerance against the depth a tap's plane puts under the pixel */
    ssao_output_format output_format;           /**< plugin-owned output format; default R8 */
    /* ---- appended in interface 1.1 (a 1.0-sized struct reads them as zero = default) */
    ssao_method method;          /**< estimator; default: the DEFAULT preset's (visibility) */
    float thickness;             /**< visibility: how far behind the depth buffer a step still counts
                                    as blocked, view-space units, > 0; default
                                    radius * (0.5 + 1.5 / step_count), 0.875 * radius at 4 steps
                                    (a huge value such as 1e30 gives the height-field assumption) */
    uint32_t step_count;         /**< visibility: steps per direction, 1..32; default: see sample_count */
    ssao_resolution resolution;  /**< grid the sampling pass runs on; default: see sample_count. Below full the
                                    blur runs on that grid and a depth-aware upsample follows */
    /* ---- appended in interface 1.2 (older structs read them as zero = off) */
    float fade_start;            /**< distance fade: view depth (view-space units along the view axis) where AO
                                    starts to fade to 1, >= 0; default 0. Only with fade_end */
    float fade_end;              /**< view depth where AO has faded to 1 (no occlusion beyond), > fade_start,
                                    finite; 0 = no fade (default): no instruction of it runs */
    float radius_pixels;         /**< > 0: the sampling radius is given in viewport pixels at each pixel's
                                    depth (the view-space size of that many pixels there), clamped to at
                                    most `radius` view units, (0, 16384]; 0 = off (default): radius is
                                    view units. thickness and bias scale with the per-pixel radius */
    ssao_debug_view debug_view;  /**< what to write instead of the AO; default none */
    /* ---- appended in interface 1.4 (older structs read it as zero = off) */
    float max_step_texels;       /**< visibility: > 0: the longest a march step may be on screen, in texels
                                    of the sampling grid (viewport pixels at full resolution, 2x2
                                    blocks at half). A direction whose march spans more than
                                    step_count such steps takes as many as keep each within it, up to
                                    SSAO_MAX_STEPS, so that a radius covering many pixels (close-ups,
                                    large radii) does not step over thin occluders. The cost then grows
                                    with the radius on screen, so with the resolution too, at most
                                    SSAO_MAX_STEPS / step_count times (docs/benchmark.md, "Step
                                    length": 4 gains most in close-ups). (0, 1e6], not a denormal;
                                    0 = off (default): step_count steps */
} ssao_settings;

/** sizeof(ssao_settings) as interfaces 1.0 to 1.3 defined it; the library accepts them. */
#define SSAO_SETTINGS_SIZE_1_0 64u  /**< interface 1.0's ssao_settings */
#define SSAO_SETTINGS_SIZE_1_1 80u  /**< interface 1.1's ssao_settings */
#define SSAO_SETTINGS_SIZE_1_2 96u  /**< interfaces 1.2 and 1.3's ssao_settings */

/** Named quality presets, picked from the front of error against CPU time (llvmpipe)
 * that ssao-bench measures, by the rule stated in the README ("Presets").
 * preset_settings sets the fields below and leaves every other field 0
 * (radius, bias, thickness, ...: default, derived when the settings are
 * resolved), so a radius set after taking a preset also scales the bias and
 * thickness. A zeroed ssao_settings resolves to SSAO_PRESET_DEFAULT. The
 * comments are tested against preset_settings (tests/host/test_presets_doc.cpp). */
typedef enum ssao_preset {
    SSAO_PRESET_DEFAULT = 0,    /**< = SSAO_PRESET_MEDIUM, the recommended default */
    SSAO_PRESET_LOW = 1,        /**< visibility, 4 directions x 8 steps, quarter resolution, depth-aware blur */
    SSAO_PRESET_MEDIUM = 2,     /**< visibility, 8 directions x 4 steps, half resolution, no blur */
    SSAO_PRESET_HIGH = 3,       /**< visibility, 4 directions x 4 steps, full resolution, depth-aware blur */
    SSAO_PRESET_ULTRA = 4,      /**< visibility, 8 directions x 8 steps, full resolution, depth-aware blur */
    SSAO_PRESET_CHAPTER = 5,    /**< kernel, 64 accelerating samples, full resolution, 4x4 box blur */
                                /** (1.1) the LearnOpenGL chapter's configuration, the textbook
                                   baseline: not picked by the rule, kept one flag away */
    SSAO_PRESET_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_preset;

/* ----------------------------------------------------------------- inputs */
/** The depth range the projection's clip space maps to (glClipControl's depth mode). */
typedef enum ssao_clip_range {
    SSAO_CLIP_DEFAULT = 0,            /**< = SSAO_CLIP_NEGATIVE_ONE_TO_ONE */
    SSAO_CLIP_NEGATIVE_ONE_TO_ONE = 1,/**< GL's default: depth = ndc_z * 0.5 + 0.5 */
    SSAO_CLIP_ZERO_TO_ONE = 2, /**< glClipControl(..., GL_ZERO_TO_ONE): depth = ndc_z */
    SSAO_CLIP_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_clip_range;

/** The space the host's normals are stored in (inputs.normal_space). */
typedef enum ssao_normal_space {
    SSAO_NORMAL_SPACE_DEFAULT = 0,    /**< = SSAO_NORMAL_SPACE_VIEW */
    SSAO_NORMAL_SPACE_VIEW = 1,       /**< view space: the camera looks down -z */
    SSAO_NORMAL_SPACE_WORLD = 2, /**< rotated into view space with ssao_inputs.view_matrix */
    SSAO_NORMAL_SPACE_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_normal_space;

/** How the host's normal texture stores a unit normal (inputs.normal_packing). */
typedef enum ssao_normal_packing {
    SSAO_NORMAL_PACKING_DEFAULT = 0,  /**< = SSAO_NORMAL_PACKING_UNORM */
    SSAO_NORMAL_PACKING_UNORM = 1,    /**< stored as n * 0.5 + 0.5 in [0,1] (RGB8, RGBA8, RGB10A2, ...) */
    SSAO_NORMAL_PACKING_SIGNED = 2, /**< stored as is (RGB16F, RGBA16F, RGB32F, RGB8_SNORM, ...) */
    SSAO_NORMAL_PACKING_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_normal_packing;

/** (1.2) How the AO reaches a host output texture (inputs.output_mode). */
typedef enum ssao_output_mode {
    SSAO_OUTPUT_MODE_DEFAULT = 0,     /**< = SSAO_OUTPUT_MODE_OVERWRITE */
    SSAO_OUTPUT_MODE_OVERWRITE = 1,   /**< the viewport rectangle's channels are overwritten: rgb = AO, a = 1 */
    SSAO_OUTPUT_MODE_MULTIPLY = 2,    /**< the host's lit image: its RGB at the viewport rectangle is multiplied
                                         by AO through blending (alpha untouched); needs output_texture.
                                         An sRGB texture is multiplied in linear space. With strength
                                         SSAO_STRENGTH_OFF no pass runs (passes_run 0) and the texture is
                                         untouched; ssao_output still names it at the viewport's origin.
                                         A debug view is not multiplied: it overwrites (ssao_debug_view) */
    SSAO_OUTPUT_MODE_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_output_mode;

/** What one execute reads and where it writes: the host's textures, its
 * projection and the viewport. */
typedef struct ssao_inputs {
    uint32_t size;               /**< sizeof(ssao_inputs) */
    uint32_t depth_texture;      /**< GL_TEXTURE_2D, D16/D24/D24S8/D32F/D32FS8; required. (1.2) Or a
                                    GL_TEXTURE_2D_MULTISAMPLE: sample_index is read at every pixel */
    uint32_t normal_texture;     /**< a texture of the same size and target (and sample count), xyz = normal.
                                    (1.2) 0: view-space normals are reconstructed from depth */
    ssao_normal_space normal_space;     /**< the space normal_texture's normals are in */
    ssao_normal_packing normal_packing; /**< how normal_texture stores them */
    float projection[16];        /**< the projection that rendered the depth, column-major.
                                    Perspective (any near/far, infinite far, reverse-Z,
                                    off-centre, jittered) or orthographic; which one, and
                                    whether depth is reversed, is read from the matrix.
                                    Taken up to a positive scale: k P gives P's AO. */
    float view_matrix[16];       /**< world -> view, column-major; read only for world-space
                                    normals (its upper 3x3 must be a rotation) */
    ssao_clip_range clip_range;  /**< the clip-control depth mode the depth was rendered with */
    int32_t viewport[4];         /**< x, y, width, height in pixels of the input textures; all
                                    zero = the whole depth texture. The projection maps this
                                    rectangle to NDC [-1,1]^2, as glViewport does. */
    uint32_t output_texture;     /**< 0: the library renders into its own texture (format from
                                    settings.output_format, viewport-sized, texel (0,0) =
                                    viewport pixel (x,y)) and returns it in ssao_output.
                                    Otherwise a colour-renderable GL_TEXTURE_2D of the host's
                                    (not an input), written at the same viewport rectangle: every
                                    channel there is overwritten, red = green = blue = AO, alpha = 1
                                    (or multiplied, see output_mode). */
    /* ---- appended in interface 1.2 (older structs read them as zero = today's behaviour) */
    uint32_t sample_index;       /**< multisampled inputs (GL_TEXTURE_2D_MULTISAMPLE depth and normal): the
                                    sample read at every pixel, < the textures' sample count; default 0.
                                    Ignored for single-sample inputs */
    ssao_output_mode output_mode;/**< default: overwrite */
    uint32_t frame_index;        /**< 0: the fixed noise pattern of every earlier version. Otherwise the
                                    per-pixel rotation and step jitter move along a low-discrepancy sequence
                                    indexed by it, so a host's TAA averages the noise away: pass the frame
                                    number (any uint32; a fixed index gives bit-identical output). With
                                    rotation NONE the whole kernel turns from frame to frame. Below full
                                    resolution each block's picked pixel alternates between two corners
                                    (odd and even indices) and the upsample fits a plane through its
                                    taps, so the averaged AO keeps no pattern of the grid's picked pixels. The first
                                    execute with a nonzero index compiles the variants that do this
                                    (a one-time cost; SHADER if the driver cannot compile them) */
} ssao_inputs;

/** sizeof(ssao_inputs) as interfaces 1.0 and 1.1 defined it; the library accepts it. */
#define SSAO_INPUTS_SIZE_1_1 172u

/** Where execute left the AO and which passes it ran. */
typedef struct ssao_output {
    uint32_t size;               /**< sizeof(ssao_output) */
    uint32_t texture;            /**< the texture holding AO: output_texture or the library's */
    int32_t origin[2];           /**< where the viewport's AO starts in `texture` (pixels) */
    uint32_t passes_run;         /**< bit mask of ssao_pass: what this execute actually ran */
} ssao_output;

/** The passes of one execute, as bits of ssao_output.passes_run and values of ssao_timings.pass_kind. */
typedef enum ssao_pass {
    SSAO_PASS_OCCLUSION = 1,     /**< the occlusion estimator: the kernel or the visibility method */
    SSAO_PASS_BLUR_X = 2,        /**< horizontal blur (or the box blur's single pass) */
    SSAO_PASS_BLUR_Y = 4,        /**< vertical blur */
    SSAO_PASS_CLEAR = 8,         /**< strength 0 (or BLUR_WEIGHTS without a blur): output cleared to 1,
                                    nothing sampled */
    SSAO_PASS_GRID = 16,         /**< the grid pass: view z and normal of one picked texel per block into
                                    the grid the estimator reads (counted in ssao_timings.ao_ms). Runs
                                    at half/quarter resolution, and at full resolution for the visibility
                                    estimator, the depth-aware blur, multisampled inputs, depth-only input
                                    and the normals debug views */
    SSAO_PASS_UPSAMPLE = 32,     /**< half/quarter resolution: depth-aware upsample of the reduced
                                    grid's AO to every viewport pixel (counted in blur_ms) */
    SSAO_PASS_NORMALS_VIEW = 64, /**< the debug views NORMALS and RECONSTRUCTED_NORMALS: the grid's normals
                                    written to the output (counted in ao_ms) */
    SSAO_PASS_AO = SSAO_PASS_OCCLUSION,        /**< the 1.0 name of SSAO_PASS_OCCLUSION */
    SSAO_PASS_DOWNSAMPLE = SSAO_PASS_GRID,     /**< the 1.1 name of SSAO_PASS_GRID */
    /** Where KHR_debug is present each pass runs inside a debug group named
     * "ssao: grid", "ssao: kernel" or "ssao: visibility" (the estimator),
     * "ssao: normals view", "ssao: blur x", "ssao: blur y", "ssao: upsample"
     * or "ssao: clear", all inside one group "ssao" (see docs/api.md,
     * "Debugger names"). */
    SSAO_PASS_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_pass;

/** GPU times of one earlier frame, from timestamp queries read without
 * stalling: results arrive a few frames late. Needs timer queries (GL 3.3
 * core has them). One timestamp is taken before the first pass and one after
 * each pass, so the per-pass times add up to total_ms.
 * Versions: 1.0 ends at total_ms (40 bytes); 1.1 appends the per-pass times.
 * get_timings fills as much as the caller's size says (either version). */
typedef struct ssao_timings {
    uint32_t size;               /**< sizeof(ssao_timings) */
    uint32_t available;          /**< 1 when the fields below hold a measured frame */
    uint64_t frame;              /**< which successful execute (1 = first) they were measured on */
    double ao_ms;                /**< the grid pass, the estimator (or the normals view) and the clear */
    double blur_ms;              /**< all blur passes and the upsample */
    double total_ms;             /**< whole execute on the GPU (= the sum of pass_ms) */
    /** 1.1 */
    uint32_t pass_count;         /**< passes that frame ran, 0..SSAO_MAX_PASSES (0 when not available, or for a
                                      frame that ran none: strength off in MULTIPLY mode) */
    uint32_t pass_kind[SSAO_MAX_PASSES]; /**< the ssao_pass value of pass i, in the order they ran; 0 beyond pass_count */
    uint32_t reserved;           /**< 0; keeps pass_ms 8-byte aligned without implicit padding */
    double pass_ms[SSAO_MAX_PASSES];     /**< GPU time of pass i; 0 beyond pass_count */
} ssao_timings;

/** What the library read from the last execute's inputs (for tests and tools). */
typedef struct ssao_frame_info {
    uint32_t size;               /**< sizeof(ssao_frame_info) */
    uint32_t orthographic;       /**< 1 for an orthographic projection */
    uint32_t reverse_z;          /**< 1 when depth decreases with distance */
    uint32_t infinite_far;       /**< 1 when the far plane is at infinity */
    uint32_t depth_bits;         /**< 16, 24 or 32 (32 = float) */
    float near_distance;         /**< view-space distance of the near plane */
    float far_distance;          /**< of the far plane; +inf for an infinite far plane */
} ssao_frame_info;

/* ---------------------------------------------------------------- context */
/** A GL function as the host's loader returns it. */
typedef void (*ssao_gl_proc)(void);
/** The host's GL loader (e.g. a wrapper of eglGetProcAddress): the function named, or NULL. */
typedef ssao_gl_proc (SSAO_CALL *ssao_get_proc_address_fn)(void* user, const char* name);

/** How serious a message sent to ssao_context_desc.log is. */
typedef enum ssao_log_level {
    SSAO_LOG_INFO = 0,     /**< for information (e.g. a shader variant compiled) */
    SSAO_LOG_WARNING = 1,  /**< something the host may want to fix; the call went on */
    SSAO_LOG_ERROR = 2,    /**< the call failed; the same sentence as last_error */
    SSAO_LOG_MAX_ENUM = 0x7fffffff  /**< not a value: keeps the enum 32 bits wide */
} ssao_log_level;
/** Receives the library's messages (one line each, no newline), on the calling thread,
 * possibly in the middle of execute while the library's GL state is in place:
 * it must not call GL (what it changed would disturb the frame, or be undone
 * by the state guard). */
typedef void (SSAO_CALL *ssao_log_fn)(void* user, ssao_log_level level, const char* message);

/** What create_context needs: the host's GL loader, and optionally a log and initial settings. */
typedef struct ssao_context_desc {
    uint32_t size;                           /**< sizeof(ssao_context_desc) */
    ssao_get_proc_address_fn get_proc_address; /**< required: e.g. a wrapper of eglGetProcAddress */
    void* get_proc_address_user;             /**< passed back to get_proc_address */
    ssao_log_fn log;                         /**< optional: receives every error message too */
    void* log_user;                          /**< passed back to log, until destroy_context: the
                                                  context keeps it (and log) */
    const ssao_settings* settings;           /**< optional initial settings; NULL = defaults */
} ssao_context_desc;

/** One instance of the pass, bound to the GL context it was created on (opaque). */
typedef struct ssao_context ssao_context;

/* ------------------------------------------------------------- the table */
/** The function table ssao_get_api fills: the whole interface. */
typedef struct ssao_api {
    uint32_t size;               /**< sizeof(ssao_api), set by the caller */
    uint32_t version;            /**< set by the library: the version it implements */

    /** A static English sentence for a status; never NULL ("unknown status" for others). */
    const char* (SSAO_CALL *status_string)(ssao_status status);

    /** Resolves every zero (default) field of `in` and validates the rest.
     * Needs no GL. Returns OK, NULL_POINTER, STRUCT_SIZE, INVALID_ENUM,
     * INVALID_VALUE. */
    ssao_status (SSAO_CALL *resolve_settings)(const ssao_settings* in, ssao_settings* out);

    /** Fills `out` (whose size the caller set) with a preset: the fields its
     * row sets, every other field 0 (resolve_settings shows what they become).
     * Returns OK, NULL_POINTER, STRUCT_SIZE, INVALID_ENUM. */
    ssao_status (SSAO_CALL *preset_settings)(ssao_preset preset, ssao_settings* out);

    /** Loads GL through desc->get_proc_address, compiles the shaders and makes
     * the GL objects. A GL context must be current. *out is NULL on failure.
     * Returns OK, NULL_POINTER, STRUCT_SIZE, INVALID_ENUM, INVALID_VALUE,
     * GL_VERSION, GL_LOAD, SHADER, OUT_OF_MEMORY, INTERNAL. The reason is also sent to
     * desc->log, since there is no context to ask. */
    ssao_status (SSAO_CALL *create_context)(const ssao_context_desc* desc, ssao_context** out);

    /** Deletes the context and its GL objects; NULL is allowed (returns OK).
     * The GL context it was created on must be current. On any other GL
     * context (or none) it deletes no GL object (the names may be the current
     * context's own), frees the library's memory all the same (ctx is invalid
     * afterwards) and returns WRONG_CONTEXT: the GL objects go with the
     * creating GL context when the host destroys it. */
    ssao_status (SSAO_CALL *destroy_context)(ssao_context* ctx);

    /** Validates and applies settings (takes effect at the next execute).
     * Returns OK, NULL_POINTER, STRUCT_SIZE, INVALID_ENUM, INVALID_VALUE. */
    ssao_status (SSAO_CALL *set_settings)(ssao_context* ctx, const ssao_settings* settings);

    /** The context's resolved settings. Returns OK, NULL_POINTER, STRUCT_SIZE. */
    ssao_status (SSAO_CALL *get_settings)(const ssao_context* ctx, ssao_settings* out);

    /** Renders AO for inputs->viewport. `out` may be NULL. Returns OK,
     * NULL_POINTER, STRUCT_SIZE, INVALID_ENUM, INVALID_VALUE, INVALID_SIZE,
     * INVALID_TEXTURE, UNSUPPORTED_FORMAT, INVALID_PROJECTION, FRAMEBUFFER,
     * OUT_OF_MEMORY, INTERNAL, and (1.2) SHADER: a feature that is off by
     * default compiles its shader variant the first time a frame uses it;
     * WRONG_CONTEXT when the creating GL context is not current. */
    ssao_status (SSAO_CALL *execute)(ssao_context* ctx, const ssao_inputs* inputs, ssao_output* out);

    /** GPU times of the newest frame whose queries have completed, without
     * waiting. available = 0 until one has. out->size may be the 1.0 size
     * (40: only the fields up to total_ms are written) or sizeof(ssao_timings);
     * out->size is left as given. Returns OK, NULL_POINTER, STRUCT_SIZE, and
     * WRONG_CONTEXT (out untouched) when the creating GL context is not
     * current: the timer queries live there. */
    ssao_status (SSAO_CALL *get_timings)(ssao_context* ctx, ssao_timings* out);

    /** What the last successful execute read from its inputs (every field 0
     * before the first). Returns OK, NULL_POINTER, STRUCT_SIZE. */
    ssao_status (SSAO_CALL *get_frame_info)(const ssao_context* ctx, ssao_frame_info* out);

    /** The context's last error message ("" when none); valid until the next
     * call on the context. NULL ctx gives a static message. */
    const char* (SSAO_CALL *last_error)(const ssao_context* ctx);
} ssao_api;

/** The one exported function. Fills api (api->size set by the caller; a
 * smaller, older table gets its prefix). Returns OK, NULL_POINTER,
 * STRUCT_SIZE (size smaller than the version-1.0 table), VERSION_MISMATCH. */
typedef ssao_status (SSAO_CALL *PFN_ssao_get_api)(uint32_t requested_version, ssao_api* api);

/** Marks the one exported function: hosts see a plain declaration; the library's build defines
 * SSAO_BUILDING_LIBRARY. */
#if defined(SSAO_BUILDING_LIBRARY) && defined(_WIN32)
#  define SSAO_EXPORT __declspec(dllexport)
#elif defined(SSAO_BUILDING_LIBRARY)
#  define SSAO_EXPORT __attribute__((visibility("default")))
#else
#  define SSAO_EXPORT
#endif
/** The one exported function (see PFN_ssao_get_api): fills `api` with the interface
 * `requested_version` asks for. */
SSAO_EXPORT ssao_status SSAO_CALL ssao_get_api(uint32_t requested_version, ssao_api* api);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SSAO_SSAO_H */
