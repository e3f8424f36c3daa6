/* The frame graph's vocabulary (Filament's FrameGraph setup/execute, in C): a pass is declared once
 * in the pass table (pass_table.c) with its name, its programs, a declare step (which targets it
 * reads, samples, writes and clears, its fixed state and what it needs of the lights, for a given
 * configuration and scene), a permute step (its programs' #defines once the plan is final) and an
 * execute step (its GL work). The planner (plan.c) selects and orders passes from the table, the
 * compile step (graph.c) turns the plan into GL objects, the frame (frame.c) runs them, handing each
 * execute step only what its pass declared (tl__pass_ctx): never the renderer. */
#ifndef TL_RENDER_PASS_H
#define TL_RENDER_PASS_H

#include <stddef.h>

#include "device.h"
#include "option_check.h"
#include "permutation.h"
#include "targets.h"

#define TL__PASS_MAX_PROGRAMS 6 /* programs of one pass (lights: one per light type; material: one per model) */
#define TL__PASS_MAX_QUERIES 3  /* samples-passed queries a pass issues itself */
#define TL__PASS_MAX_TARGETS 8  /* targets one pass declares (the G-buffer pass: depth, RT0, RT1, fat's, HDR) */

typedef struct tl__scene_gpu tl__scene_gpu; /* scene_gpu.h */
typedef struct tl__lights tl__lights;       /* lights.h */
typedef struct tl__shadows tl__shadows;     /* shadows.h */
typedef struct tl__view tl__view;           /* view.h */

/* How a mode lays out the frame: one row per mode (modes.c), read by the passes' declare steps. */
typedef struct tl__mode_def {
    tl_target_set gbuffer_writes; /* colour targets the G-buffer pass writes (dropped when nobody reads them) */
    tl_target_set light_reads; /* targets the light pass reads (depth is also depth-tested) */
    tl_target_set light_samples; /* of those, the ones it samples */
    tl_target_set light_writes; /* light buffer, or HDR (blended onto) */
    uint8_t light_flag;      /* what the light shader does: TL__F_LIGHT_ACCUM, TL__F_LIGHT_SHADE_* */
    uint8_t material_pass;   /* a second geometry pass applies materials to the light buffer */
    uint8_t forward;         /* no G-buffer: objects are shaded with their light lists */
    uint8_t visibility;      /* a visibility buffer: depth and a triangle id; vis-resolve shades with the tile lists */
} tl__mode_def;

extern const tl__mode_def tl__modes[TL_MODE_COUNT_];

/* What planning starts from: resolved options and the scene's features (all of them with
 * planning off), with facts several passes share. */
typedef struct tl__plan_input {
    tl_renderer_desc d;         /* resolved: size and options */
    tl_renderer_options asked;  /* the options as the caller gave them, zeroes unresolved (the downgrades) */
    const tl_renderer_options *o; /* &d.options: what the passes read */
    tl_scene_feature_set f;
    const tl__mode_def *mode;
    int lights;                 /* any light to draw */
    uint32_t light_shift;       /* the light buffer is the frame's size over 2^light_shift (tl__light_shift) */
    tl_light_strategy strategy; /* volumes or tiled (resolved) */
    char strategy_reason[96];
    uint32_t tile_size, tiles_x, tiles_y;
    int tiled_compute;          /* tiled, deferred modes: the light pass is the compute pass (tl__plan_strategy) */
    int spec;                   /* specular materials */
    tl_lighting_model lighting; /* resolved: blinn-phong or ggx */
    tl_fresnel_layout fresnel;  /* thin-lpp, GGX, specular: the light buffer's Fresnel layout; else DEFAULT */
    char lighting_reason[96];
    /* every lighting program's model switches: TL_SPECULAR_EXACT, TL_SPECULAR_COMPACT or
     * TL_SPECULAR_NONE, then TL_GGX with GGX, then TL_FRESNEL_SUMS or TL_FRESNEL_NV in thin-lpp,
     * TL_SHADOWS (and TL_PCSS) with casting lights */
    tl__perm spec_perm;
    unsigned rt0_flag;          /* TL__F_RT0_RGBA8 or TL__F_RT0_RGB10A2 */
    tl__perm material;          /* the geometry passes' material switches */
    uint32_t msaa;              /* samples of the multisampled targets (tl__msaa_samples), 1: no MSAA */
    int stipple;                /* the blended materials go through the G-buffer's 2x2 stipple (pass_stipple.c) */
    char transparency_reason[96];
    const char *transparency_why; /* blended materials drawn forward: why not the stipple (NULL otherwise) */
    uint32_t shadows;           /* casting lights looked up (TL_SHADOWS in spec); 0: none */
    int coat_sums;              /* thin-lpp, a clearcoat drawn, sums asked or auto: the coat's own sums (material_models.c) */
    const char *coat_why;       /* a clearcoat drawn, sums asked or auto, but the approximation planned: why */
} tl__plan_input;

/* What a pass needs of the lights module each frame (tl__pass_decl.light_data). */
enum {
    TL__LIGHTS_INSTANCES = 1u,    /* light-volume instances by type (light_volumes.c) */
    TL__LIGHTS_VIEW = 2u,         /* the visible lights in view space, bound as a storage block */
    TL__LIGHTS_INDEX_BUFFER = 4u, /* the per-object lists' storage block bound (forward.frag declares it) */
    TL__LIGHTS_OBJECT_LISTS = 8u, /* per-object light lists built (forward, transparent) */
    TL__LIGHTS_TILES = 16u        /* the tiled light lists, grown as frames need */
};

/* One pass as declared for a plan (target sets are TL_TARGET_BIT bits). */
typedef struct tl__pass_decl {
    tl_target_set writes;  /* 0: the pass is not in this frame */
    tl_target_set optional; /* writes dropped when no later pass reads them */
    tl_target_set reads;   /* sampled, depth-tested or blended onto (lifetimes, culling) */
    tl_target_set samples; /* the reads bound to texture units */
    tl_target_set clears;  /* cleared when the pass starts */
    tl_target_set neighbourhood; /* samples read as a 5-texel cross per fragment (bytes estimate) */
    uint8_t attach_depth;  /* the depth target is attached (tested or written) */
    uint8_t depth_target;  /* which: a tl_target_id, 0 (TL_TARGET_DEPTH) or TL_TARGET_LIGHT_DEPTH */
    uint8_t compute;       /* a compute pass, or one that draws into its module's own framebuffer: no
                              framebuffer, clears or raster state of the graph's */
    uint8_t light_data;    /* TL__LIGHTS_* it reads */
    uint8_t split_writes;  /* it renders its colour writes one at a time: a framebuffer per write too */
    tl_target_set images;  /* writes bound as images (compute passes) */
    tl_target_set sinks;   /* writes read after the frame (a debug output): never culled, kept to the end */
    tl__pipeline state;    /* fixed state; a pass may change cull, depth test and clamp per draw */
} tl__pass_decl;

/* The switches of each of a pass's programs (permutation.h); a slot not used leaves the program out. */
typedef struct tl__pass_defines {
    tl__perm slot[TL__PASS_MAX_PROGRAMS];
    uint8_t used[TL__PASS_MAX_PROGRAMS];
} tl__pass_defines;

/* What a pass's execute step counts. */
typedef struct tl__pass_out {
    uint32_t draw_calls;
    size_t indices;   /* scene indices drawn (vertex fetch) */
    size_t instances; /* light instances drawn */
} tl__pass_out;

/* What a pass's execute step gets: the GL objects its declaration resolved to (its framebuffer
 * bound, its samples on their units, its images bound, its state applied), its programs, and the
 * services its definition asked for. */
typedef struct tl__pass_ctx {
    const GladGLContext *gl;
    tl__state *state;
    const GLuint *programs;       /* by slot; 0 where the plan has none */
    const tl__pipeline *pipeline; /* its declared state, as applied */
    GLuint fbo;                   /* its framebuffer (0 for compute passes) */
    /* its one colour write with mip levels: a framebuffer and a one-level view per level */
    uint32_t level_count;
    const GLuint *level_fbos, *level_textures;
    uint32_t level_width, level_height; /* the first level's size */
    /* split_writes: a framebuffer with each colour write alone, and its texture (tl_target_id order) */
    uint32_t write_count;
    const GLuint *write_fbos, *write_textures;
    uint32_t width, height;       /* the frame's size */
    uint32_t light_shift;         /* the light scale: the light buffer is the frame's size >> light_shift */
    uint32_t gbuffer_samples;     /* MSAA per-sample edges: the samples the G-buffer has (tl__graph.samples); else 1 */
    GLuint fullscreen_vao, linear_sampler;
    const uint8_t *unit_of;       /* the texture unit of each target it samples (TL__UNIT_NONE otherwise) */
    const void *params;           /* its slice of the resolved options (tl__pass_def.options_offset), or NULL */
    const GLuint *queries;        /* its own samples-passed queries (query_count), NULL when not measured */
    int to_caller;                /* it writes the output into the caller's framebuffer */
    uint64_t frame;               /* the frame's index */
    tl__pass_out *out;
    const tl__scene_gpu *scene;   /* TL__PASS_SCENE: the visible objects, to draw */
    tl__lights *lights;           /* TL__PASS_LIGHTS: the frame's light data */
    tl__shadows *shadows;         /* TL__PASS_SHADOWS: the shadow module, */
    tl__device *device;           /* the device it creates its GL objects on, */
    tl_frame_stats *stats;        /* and the frame's statistics it fills */
} tl__pass_ctx;

/* What a pass that the options turn on (tl__pass_def.wanted) makes the frame give up
 * (tl__pass_def.refuses): the planner derives its refusals from these, naming no pass. */
enum {
    TL__REFUSES_MSAA = 1u,   /* it reads a one-sample HDR and depth: no multisampled frame */
    TL__REFUSES_STIPPLE = 2u /* it reads depth after the stipple's transparent layers wrote theirs */
};

/* Services a pass's definition asks for (tl__pass_def.services): the scene on the GPU, the frame's
 * light data, the shadow module with the device (its atlas and buffers) and the frame's statistics
 * (what the pass did beyond its draws). */
enum { TL__PASS_SCENE = 1u, TL__PASS_LIGHTS = 2u, TL__PASS_SHADOWS = 4u };

/* A pass's slice of tl_renderer_options and its rows of the option registry (option_check.h), e.g.
 * `TL__OPTIONS(ssao, tl__ssao_rows)` in its definition. */
#define TL__OPTIONS(field, rows)                                                                  \
    .options_name = #field, .options_offset = offsetof(tl_renderer_options, field),               \
    .options_size = sizeof(((tl_renderer_options *)0)->field), .option_rows = (rows),             \
    .option_row_count = sizeof(rows) / sizeof((rows)[0])

typedef struct tl__pass_def {
    tl_pass id;       /* its stable public index (statistics); the table's order is the frame's */
    const char *name;
    tl__program_src programs[TL__PASS_MAX_PROGRAMS + 1];
    const tl__target_def *targets[TL__PASS_MAX_TARGETS]; /* the targets it owns (declares) */
    /* its options (TL__OPTIONS): their rows of the option registry (name, range, default, help;
     * checked before resolve, zeroes with one default value already given it), and resolve for what
     * is left: an effect that is off zeroed whole (so its other fields cannot change a plan),
     * defaults computed from other fields */
    const char *options_name;
    size_t options_offset, options_size;
    const tl_option_info *option_rows;
    size_t option_row_count;
    void (*resolve)(void *options);
    /* its std140 parameter block, bound at TL_UBO_PASS while it runs (frame.glsl has the frame's):
     * params writes it from the resolved options and the view (NULL outside a frame) */
    uint32_t params_size;
    void (*params)(const tl_renderer_options *o, const tl__view *v, void *block);
    void (*declare)(const tl__plan_input *in, tl__pass_decl *d);
    void (*permute)(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out);
    void (*execute)(const tl__pass_ctx *ctx);
    /* optional: files its own queries' results (query_count of them; else its samples-passed count,
     * `fragments`, against the frame's `pixels`) and its GPU time `ms` into the stats */
    void (*collect)(const uint64_t *results, uint64_t fragments, uint64_t pixels, double ms, tl_frame_stats *st);
    uint8_t query_count;
    uint8_t services; /* TL__PASS_* its execute step reads */
    /* optional: whether the (resolved) options turn the pass on, and what the frame then gives up
     * (TL__REFUSES_*) */
    int (*wanted)(const tl_renderer_options *o);
    uint8_t refuses;
    /* optional: its CPU work before the frame's data is uploaded (the shadows pass chooses the
     * casting lights' views), with the services it asked for, the frame's view and options */
    tl_result (*prepare)(const tl__pass_ctx *ctx, const tl__view *v, const tl_renderer_options *o);
    const char *refuses_why[2]; /* why, per TL__REFUSES_* bit in order: MSAA's, the stipple's */
} tl__pass_def;

/* pass_shadows.c: the plan's casting lights and the lighting programs' shadow switches. */
void tl__shadows_plan(tl__plan_input *in);

/* pass_table.c: why the first pass the options turn on refuses `what` (one TL__REFUSES_* bit), or
 * NULL when none does. */
const char *tl__passes_refuse(const tl_renderer_options *o, unsigned what);

/* What the light pass reads and writes in a mode, whichever strategy gathers the lights
 * (pass_lights.c; the tiled pass uses it too). */
void tl__light_pass_targets(const tl__plan_input *in, tl__pass_decl *d);
/* The light buffer's targets in `full` (LIGHT_DIFFUSE, _SPECULAR, _FRESNEL) swapped for their reduced
 * copies (LIGHT_REDUCED_*), which the light pass writes at a light scale below 1 (pass_lights.c). */
tl_target_set tl__light_buffer_reduced(tl_target_set full);
void tl__light_pass_defines(const tl__plan_input *in, const tl__pass_decl *d, tl__perm *k);
/* Forward shading reads tile lists (Forward+) in this plan; it has a depth pre-pass (modes.c). */
int tl__forward_plus(const tl__plan_input *in);
int tl__forward_prepass(const tl__plan_input *in);
/* The depth the passes drawing into HDR after the opaque frame test against: DEPTH, or with MSAA
 * in thin-lpp the material pass's multisampled depth.msaa (pass_geometry.c). */
tl_target_id tl__shading_depth(const tl__plan_input *in);
/* The depth and RT0 formats in a configuration (pass_geometry.c; the light scale's reduced copies too). */
uint32_t tl__depth_format(const tl_renderer_options *o);
uint32_t tl__rt0_format(const tl_renderer_options *o);
/* The state of a full-screen triangle pass: colour and depth writes on, nothing else (modes.c). */
extern const tl__pipeline tl__pipeline_fullscreen;
/* The permute step of a pass with one program and no defines of its own (modes.c). */
void tl__permute_one_program(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out);
/* SSAO in this plan (modes.c): 0 none, 1 read by the shading pass (material or forward), 2 taken
 * from HDR by the ssao-apply pass (thin-deferred, fat); and the defines of a shading pass that
 * samples it (" TL_SSAO_AMBIENT", " TL_SSAO_DIFFUSE", "" when it does not). */
int tl__ssao_pass(const tl__plan_input *in);
/* Whether the shadow-debug pass is in the plan (pass_shadow_debug.c). */
int tl__shadow_debug_planned(const tl__plan_input *in);
void tl__ssao_perm(const tl__plan_input *in, const tl__pass_decl *d, tl__perm *k);

/* Execute steps several passes share (draw.c): a full-screen triangle with the first program;
 * the scene's visible opaque or transparent triangles, or its points and lines, with the first
 * program. */
void tl__draw_fullscreen(const tl__pass_ctx *ctx);
void tl__draw_opaque(const tl__pass_ctx *ctx);
/* The opaque objects whose material has model `model`, with the pass's program of that slot. */
void tl__draw_opaque_model(const tl__pass_ctx *ctx, uint32_t model);
void tl__draw_transparent(const tl__pass_ctx *ctx);
/* material_models.c: the models the plan shades (1u << tl_material_model; the standard one when
 * the features name none), whether some model is not the standard one (TL_MATERIAL_MODELS), the
 * material pass's program per model (`base` with each one's TL_MODEL) and its draws. */
uint32_t tl__plan_models(const tl_scene_feature_set *f);
int tl__plan_has_models(const tl_scene_feature_set *f);
void tl__material_model_slots(const tl__plan_input *in, const tl__perm *base, tl__pass_defines *out);
/* Whether the clearcoat's own sums are planned (tl__plan_input.coat_sums); *why: why not, where a
 * clearcoat is drawn and the sums were asked or are the default (NULL otherwise). */
int tl__plan_coat_sums(const tl__plan_input *in, const char **why);
void tl__material_models_draw(const tl__pass_ctx *ctx);
void tl__draw_points_lines(const tl__pass_ctx *ctx);

/* The table, in execution order; application passes go between its entries. */
extern const tl__pass_def *const tl__pass_table[TL_PASS_COUNT];
/* Private passes the frame never plans: luma for tl_renderer_apply_fxaa. */
extern const tl__pass_def tl__pass_luma;
/* Index in tl__pass_table of the built-in pass named `name`, -1 for none (pass_table.c). */
int tl__pass_table_find(const char *name);

/* An application pass as the renderer keeps it. */
typedef struct tl__app_pass {
    tl_app_pass_desc desc;
    char name[32];
    int anchor;  /* index in tl__pass_table */
    int after;   /* 1: after the anchor, 0: before it */
} tl__app_pass;

/* A plan with what the compile step needs beyond the public description. */
typedef struct tl__plan {
    tl_frame_plan pub;
    const tl__target_def *targets[TL_TARGET_COUNT]; /* every target's definition (targets.h) */
    tl__pass_decl decl[TL_PLAN_MAX_PASSES];
    const tl__pass_def *def[TL_PLAN_MAX_PASSES]; /* NULL for application passes */
    int8_t app[TL_PLAN_MAX_PASSES];              /* application pass index, -1 for built-in ones */
    tl_target_set shared;                        /* targets whose memory a later target reuses */
    tl__perm perms[TL_PLAN_MAX_PROGRAMS];        /* each program's key (pub.programs' order) */
    char refused[64];                            /* a switch whose value a key cannot hold: "TL_NAME=value" */
} tl__plan;

#endif
