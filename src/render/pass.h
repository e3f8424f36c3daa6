/* The frame graph's vocabulary: a pass is declared once in the pass table (pass_table.c) with its
 * name, its programs, a declare step (which targets it reads, samples, writes and clears, and its
 * fixed state, for a given configuration and scene), a permute step (its programs' #defines once
 * the plan is final) and an execute step (its GL work). The planner (plan.c) selects and orders
 * passes from the table, the compile step (graph.c) turns the plan into GL objects, the frame
 * (frame.c) runs them. Nothing else knows which pass is which. */
#ifndef TL_RENDER_PASS_H
#define TL_RENDER_PASS_H

#include "gl/state.h"
#include "thinlight/renderer.h"

#define TL__PASS_MAX_PROGRAMS 3 /* programs of one pass (lights: one per light type) */
#define TL__PASS_MAX_QUERIES 3  /* samples-passed queries a pass issues itself */

typedef struct tl_renderer tl_renderer;

/* How a mode lays out the frame: one row per mode (modes.c), read by the passes' declare steps. */
typedef struct tl__mode_def {
    const char *name;
    uint32_t gbuffer_writes; /* colour targets the G-buffer pass writes (dropped when nobody reads them) */
    uint32_t light_reads;    /* targets the light pass reads (depth is also depth-tested) */
    uint32_t light_samples;  /* of those, the ones it samples */
    uint32_t light_writes;   /* light buffer, or HDR (blended onto) */
    const char *light_define; /* what the light shader does: TL_LIGHT_ACCUM, TL_LIGHT_SHADE_* */
    uint8_t material_pass;   /* a second geometry pass applies materials to the light buffer */
    uint8_t forward;         /* no G-buffer: objects are shaded with their light lists */
} tl__mode_def;

extern const tl__mode_def tl__modes[TL_MODE_COUNT_];

/* What planning starts from: resolved options and the scene's features (all of them with
 * no_planning), with facts several passes share. */
typedef struct tl__plan_input {
    tl_renderer_desc d;
    tl_scene_feature_set f;
    const tl__mode_def *mode;
    int lights;                 /* any light to draw */
    tl_light_strategy strategy; /* volumes or tiled (resolved) */
    char strategy_reason[96];
    uint32_t tile_size, tiles_x, tiles_y;
    int spec;                   /* specular materials */
    tl_lighting_model lighting; /* resolved: blinn-phong or ggx */
    tl_fresnel_layout fresnel;  /* thin-lpp, GGX, specular: the light buffer's Fresnel layout; else DEFAULT */
    char lighting_reason[96];
    /* every lighting program's model switches: TL_SPECULAR_EXACT, TL_SPECULAR_COMPACT or
     * TL_SPECULAR_NONE, then TL_GGX with GGX, then TL_FRESNEL_SUMS or TL_FRESNEL_NV in thin-lpp */
    char spec_define[48];
    const char *rt0_define;     /* TL_RT0_RGBA8 or TL_RT0_RGB10A2 */
    char material_defines[96];  /* the geometry passes' material switches (leading space each) */
} tl__plan_input;

/* One pass as declared for a plan (target sets are TL_TARGET_BIT bits). */
typedef struct tl__pass_decl {
    uint32_t writes;       /* 0: the pass is not in this frame */
    uint32_t optional;     /* writes dropped when no later pass reads them */
    uint32_t reads;        /* sampled, depth-tested or blended onto (lifetimes, culling) */
    uint32_t samples;      /* the reads bound to texture units */
    uint32_t clears;       /* cleared when the pass starts */
    uint32_t neighbourhood; /* samples read as a 5-texel cross per fragment (bytes estimate) */
    uint8_t attach_depth;  /* the depth target is attached (tested or written) */
    uint8_t compute;       /* a compute pass: no framebuffer, no clears, no raster state */
    uint8_t object_lights; /* it reads the per-object light lists (forward_lists.c) */
    uint32_t images;       /* writes bound as images (compute passes) */
    tl__pipeline state;    /* fixed state; a pass may change cull, depth test and clamp per draw */
} tl__pass_decl;

/* The defines of each of a pass's programs ("" leaves the slot out). */
typedef struct tl__pass_defines {
    char slot[TL__PASS_MAX_PROGRAMS][192];
    uint8_t used[TL__PASS_MAX_PROGRAMS];
} tl__pass_defines;

typedef struct tl__program_src {
    const char *name; /* NULL ends the list */
    const char *vs, *fs;
    const char *cs;   /* a compute program instead */
} tl__program_src;

typedef struct tl__compiled_pass tl__compiled_pass;
typedef struct tl__frame_record tl__frame_record;
typedef struct tl__view tl__view;

/* What a pass's execute step gets. */
typedef struct tl__pass_ctx {
    const tl__compiled_pass *cp;
    const tl__view *view;
    tl__frame_record *rec;  /* CPU counters of the frame */
    size_t index;           /* the pass's position in the plan */
    const GLuint *queries;  /* its own samples-passed queries (query_count), NULL when not measured */
    int to_caller;          /* it writes the output into the caller's framebuffer */
} tl__pass_ctx;

typedef struct tl__pass_def {
    tl_pass id;
    const char *name;
    tl__program_src programs[TL__PASS_MAX_PROGRAMS + 1];
    void (*declare)(const tl__plan_input *in, tl__pass_decl *d);
    void (*permute)(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out);
    /* optional CPU work before the frame's passes run (once per frame however many passes share
     * it), adding the bytes it will put in the frame's stream to rec->stream_bytes; then upload
     * writes them once the stream has room */
    tl_result (*prepare)(tl_renderer *r, const tl__view *v, tl__frame_record *rec);
    void (*upload)(tl_renderer *r);
    void (*execute)(tl_renderer *r, const tl__pass_ctx *ctx);
    /* optional: files its results into the stats: its own queries' (query_count of them) and
     * whatever else it measured for that frame */
    void (*collect)(tl_renderer *r, const uint64_t *results, tl_frame_stats *st);
    uint8_t query_count;
} tl__pass_def;

/* What the light pass reads and writes in a mode, whichever strategy gathers the lights
 * (pass_lights.c; the tiled pass uses it too). */
void tl__light_pass_targets(const tl__plan_input *in, tl__pass_decl *d);
/* Forward shading reads tile lists (Forward+) in this plan; it has a depth pre-pass (modes.c). */
int tl__forward_plus(const tl__plan_input *in);
int tl__forward_prepass(const tl__plan_input *in);
/* The state of a full-screen triangle pass: colour and depth writes on, nothing else (modes.c). */
extern const tl__pipeline tl__pipeline_fullscreen;
/* The permute step of a pass with one program and no defines of its own (modes.c). */
void tl__permute_one_program(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out);
/* SSAO in this plan (modes.c): 0 none, 1 read by the shading pass (material or forward), 2 taken
 * from HDR by the ssao-apply pass (thin-deferred, fat); and the defines of a shading pass that
 * samples it (" TL_SSAO_AMBIENT", " TL_SSAO_DIFFUSE", "" when it does not). */
int tl__ssao_pass(const tl__plan_input *in);
const char *tl__ssao_defines(const tl__plan_input *in, const tl__pass_decl *d);

/* The table, in execution order; application passes go between its entries. */
extern const tl__pass_def *const tl__pass_table[TL_PASS_COUNT];
/* Private passes the frame never plans: luma for tl_renderer_apply_fxaa. */
extern const tl__pass_def tl__pass_luma;

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
    tl__pass_decl decl[TL_PLAN_MAX_PASSES];
    const tl__pass_def *def[TL_PLAN_MAX_PASSES]; /* NULL for application passes */
    int8_t app[TL_PLAN_MAX_PASSES];              /* application pass index, -1 for built-in ones */
    uint32_t shared;                             /* targets whose memory a later target reuses */
} tl__plan;

#endif
