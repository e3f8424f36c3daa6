/* thinlight-bench: what the thin G-buffer saves in memory and bandwidth, what it costs in time and
 * what it loses in image quality, against the fat G-buffer and forward shading (docs/tools.md). Shared between bench.c (command line), bench_sweep.c (the measurements),
 * bench_scene.c (scene and lights), bench_report.c (table, JSON, doc), bench_plot.c (gnuplot) and
 * bench_images.c (final images and error heat maps). */
#ifndef TL_BENCH_H
#define TL_BENCH_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/metrics.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tool_budget.h"
#include "tool_environment.h"
#include "tool_gl.h"
#include "tool_log.h"
#include "tool_options.h"
#include "tool_util.h"

#define BENCH_TOOL "thinlight-bench"
#define BENCH_EXIT_BAD_INPUT 1
#define BENCH_EXIT_BAD_USAGE 2

#define BENCH_MAX_LIGHTS 65536u     /* local lights per frame */
#define BENCH_MAX_SIDE 16384u       /* pixels per side */
#define BENCH_MAX_LIGHT_COUNTS 32u
#define BENCH_MAX_SIZES 8u
#define BENCH_MAX_FRAMES 1000u
#define BENCH_MODES (TL_MODE_COUNT_ - 1) /* every mode but DEFAULT */
#define BENCH_STRATEGIES (TL_LIGHT_STRATEGY_COUNT_) /* auto, volumes, tiled */
#define BENCH_CONFIGS (BENCH_MODES * BENCH_STRATEGIES * 6) /* x 6: as asked, R11G11B10F, Fresnel n.v, light 1/2, 1/4, tiled compute */
#define BENCH_REFERENCE TL_MODE_FAT
/* A pass's bit in bench_record.passes: tl_pass has more than 32 values (vis-resolve is the 33rd). */
#define BENCH_PASS_BIT(p) ((uint64_t)1 << (p))
#define BENCH_PNG_MAX_BYTES (300u * 1024u)
/* Heat maps show |mode - fat| of the final image, largest RGB channel, 0..HEAT_SCALE 8-bit steps. */
#define BENCH_HEAT_SCALE 16u
/* Edge pixels (bench_edges.c): within BENCH_EDGE_RADIUS pixels (a square) of a depth discontinuity
 * (fat's linear view depth: |d(x-1) + d(x+1) - 2 d(x)| over BENCH_EDGE_DEPTH of d(x), along x or y)
 * or a normal crease (fat's normals of neighbouring pixels more than BENCH_EDGE_CREASE_DEG apart). */
#define BENCH_EDGE_RADIUS 2
#define BENCH_EDGE_DEPTH 0.02
#define BENCH_EDGE_CREASE_DEG 30.0

#define BENCH_DOC_BEGIN "<!-- bench:begin -->"
#define BENCH_DOC_END "<!-- bench:end -->"

/* What the sweep renders: a mode with a light strategy, and for thin-lpp with the tiled strategy
 * two variants: the R11G11B10F light buffer (variant 1) and, when the frame is lit with GGX, the
 * cheaper Fresnel layout (variant 2, Schlick with n.v per pixel): mode + TL_MODE_COUNT_ *
 * (strategy + BENCH_STRATEGIES * variant). Its name is the mode's with the strategy
 * ("thin-lpp/tiled", "fat/volumes", "thin-lpp/auto", "thin-lpp/tiled/r11g11b10f",
 * "thin-lpp/tiled/nv"), except forward: "forward" with per-object lists (volumes), "forward+"
 * with tile lists (tiled). visibility has one configuration, "visibility/tiled": its plan lights
 * from the tile lists whatever the strategy asked (volumes is downgraded) and its resolve is a
 * compute pass, so it has no volumes, tiled-compute, light-scale or light-format variant. */
typedef unsigned bench_config;
#define BENCH_VARIANT_R11G11B10F 1u
#define BENCH_VARIANT_FRESNEL_NV 2u
#define BENCH_VARIANT_LIGHT_HALF 3u    /* thin-lpp with light_scale 0.5 (--light-scales) */
#define BENCH_VARIANT_LIGHT_QUARTER 4u /* thin-lpp with light_scale 0.25 */
#define BENCH_VARIANT_TILED_COMPUTE 5u /* thin-lpp, thin-deferred, fat with the tiled strategy's compute pass
                                          ("<mode>/tiled-compute"; "<mode>/tiled" is the fragment pass) */
static inline bench_config bench_config_make(tl_render_mode m, tl_light_strategy s)
{
    if (m == TL_MODE_VISIBILITY) s = TL_LIGHT_STRATEGY_TILED; /* what its plan does, named so */
    return (unsigned)m + (unsigned)TL_MODE_COUNT_ * (unsigned)s;
}
static inline tl_render_mode bench_config_mode(bench_config c) { return (tl_render_mode)(c % TL_MODE_COUNT_); }
static inline tl_light_strategy bench_config_strategy(bench_config c)
{
    return (tl_light_strategy)(c / TL_MODE_COUNT_ % BENCH_STRATEGIES);
}
static inline unsigned bench_config_variant_of(bench_config c) { return c / (TL_MODE_COUNT_ * BENCH_STRATEGIES); }
static inline bench_config bench_config_variant(bench_config c, unsigned variant)
{
    return c % (TL_MODE_COUNT_ * BENCH_STRATEGIES) + TL_MODE_COUNT_ * BENCH_STRATEGIES * variant;
}
/* The light buffer's format: R11G11B10F for that variant, else the default. */
static inline tl_light_format bench_config_light_format(bench_config c)
{
    return bench_config_variant_of(c) == BENCH_VARIANT_R11G11B10F ? TL_LIGHT_FORMAT_R11G11B10F
                                                                   : TL_LIGHT_FORMAT_DEFAULT;
}
/* The light scale: 2^-1 and 2^-2 for those variants, else 0 (the default, 1). */
static inline float bench_config_light_scale(bench_config c)
{
    unsigned v = bench_config_variant_of(c);
    return v == BENCH_VARIANT_LIGHT_HALF || v == BENCH_VARIANT_LIGHT_QUARTER
               ? 1.0f / (float)(2u << (v - BENCH_VARIANT_LIGHT_HALF)) : 0.0f;
}
/* The tiled light pass: compute for that variant and for visibility (its resolve is a compute pass:
 * asking it for the fragment pass would be a downgrade); the fragment pass for the others when the
 * bench measures both (`asked` auto, the default), else `asked` (--tiled-shading fragment|compute). */
static inline tl_tiled_shading bench_config_tiled_shading(bench_config c, tl_tiled_shading asked)
{
    if (bench_config_variant_of(c) == BENCH_VARIANT_TILED_COMPUTE || bench_config_mode(c) == TL_MODE_VISIBILITY)
        return TL_TILED_SHADING_COMPUTE;
    return asked == TL_TILED_SHADING_AUTO ? TL_TILED_SHADING_FRAGMENT : asked;
}
/* The Fresnel layout: n.v for that variant, else `asked` (--fresnel). */
static inline tl_fresnel_layout bench_config_fresnel(bench_config c, tl_fresnel_layout asked)
{
    return bench_config_variant_of(c) == BENCH_VARIANT_FRESNEL_NV ? TL_FRESNEL_NV : asked;
}
const char *bench_config_name(bench_config c);
/* The name for file names: '/' becomes '-', '+' becomes "-plus". */
const char *bench_config_slug(bench_config c);

typedef struct bench_size {
    uint32_t width, height;
} bench_size;

/* Screen-space effects the bench can measure (--effects), each against the same frame without it. */
typedef enum bench_effect {
    BENCH_EFFECT_SSAO,
    BENCH_EFFECT_FOG,
    BENCH_EFFECT_DOF,
    BENCH_EFFECT_BLOOM,
    BENCH_EFFECT_SSR, /* not in forward, which plans no reflections (no gloss to read) */
    BENCH_EFFECT_VIGNETTE,
    BENCH_EFFECTS
} bench_effect;
const char *bench_effect_name(bench_effect e);
/* Every effect's name in bench_effect order (its options' struct in tl_renderer_options), then
 * "none" (--effects) and NULL. */
extern const char *const bench_effect_names[BENCH_EFFECTS + 2];

/* Antialiasing methods the bench can measure (--aa), each against a supersampled truth
 * (bench_aa.c): FXAA off, FXAA (the renderer's default preset), MSAA with 2, 4 or 8 samples
 * (msaaN: thin-lpp's material pass, forward's own; msaaNe: per-sample lighting on edges over a
 * multisampled G-buffer, thin-lpp, thin-deferred and fat; tl_renderer_options.msaa_lighting). */
typedef enum bench_aa {
    BENCH_AA_NONE,
    BENCH_AA_FXAA,
    BENCH_AA_MSAA2,
    BENCH_AA_MSAA4,
    BENCH_AA_MSAA8,
    BENCH_AA_MSAA2E,
    BENCH_AA_MSAA4E,
    BENCH_AA_MSAA8E,
    BENCH_AAS
} bench_aa;
/* Every method's name in bench_aa order, then NULL (--aa). */
extern const char *const bench_aa_names[BENCH_AAS + 1];
const char *bench_aa_name(bench_aa a);
/* Samples per pixel of MSAA (1 for none and FXAA), and how MSAA lights the frame. */
uint32_t bench_aa_samples(bench_aa a);
tl_msaa_lighting bench_aa_lighting(bench_aa a);
/* The truth: fat at BENCH_AA_TRUTH_SCALE times the width and the height, FXAA off, every sample
 * tone-mapped on the CPU, each block averaged in tone-mapped linear space, then sRGB-encoded. */
#define BENCH_AA_TRUTH_SCALE 4u

typedef struct bench_options {
    const char *scene;        /* "default" or a glTF file */
    bench_size sizes[BENCH_MAX_SIZES];
    size_t size_count;
    uint32_t lights[BENCH_MAX_LIGHT_COUNTS]; /* ascending, no repeats */
    size_t light_count;
    tl_render_mode modes[BENCH_MODES];       /* as asked, no repeats */
    size_t mode_count;
    tl_light_strategy strategies[BENCH_STRATEGIES]; /* as asked, no repeats (default volumes, tiled) */
    size_t strategy_count;
    uint32_t frames, warmup;
    uint64_t seed;
    const char *json, *out, *doc;
    int quick, no_plot;
    int small_light_buffer;   /* also thin-lpp/tiled with an R11G11B10F light buffer (--light-formats) */
    unsigned light_scales;    /* --light-scales: bits 1 (1/2) and 2 (1/4): thin-lpp also at those light
                                 scales, with the first strategy asked (default both) */
    int fresnel_nv_variant;   /* also thin-lpp/tiled with the n.v Fresnel layout: set when the scene is
                                 lit with GGX and --fresnel was not given */
    tl_tool_context_args context_args; /* --context, --device, --list-devices as given */
    tl_tool_context_options context;   /* what they ask for */
    tl_tool_budgets budgets;           /* --max-target-memory, --max-load-memory, --max-texture-pixels */
    tl_renderer_options base;        /* the renderer options given (tool_options.h): every configuration's, the
                                        swept fields and the effects' `enabled` aside (bench_config_desc) */
    unsigned effects;                /* --effects and the effects' flags: bits (1u << bench_effect); 0: none */
    tl_tool_environment env;         /* --environment */
    const char *effects_doc;         /* --effects-doc: the effects table between its markers */
    unsigned aa;                     /* --aa: bits (1u << bench_aa); 0: not measured */
    const char *aa_doc;              /* --aa-doc: the AA table between its markers */
    const char *aa_section;          /* --aa-doc-section: the markers' and images' name; NULL: the default pair */
    int shadows;                     /* --shadows: 1 when "on" was given (measured against "off") */
    const char *shadows_doc;         /* --shadows-doc: the shadows' table between its markers */
} bench_options;

/* bench_args.c: the command line into `o`: 0; -1 after --help or --list-options (printed); or 2
 * (bad usage) after one line on stderr. */
int bench_parse_args(int argc, char **argv, bench_options *o);
/* The renderer options the sweep sets itself (field names, NULL-terminated) and the list flag that
 * sweeps each (its names from the field's row): --modes, --strategies, --light-formats,
 * --light-scales. The other fields are flags of their own (bench_renderer_flags). */
extern const char *const bench_swept_fields[];
extern const char *const bench_swept_flags[];
typedef struct bench_renderer_flags {
    tl_tool_options flags; /* every field's flag but the swept ones' */
    tl_tool_options swept; /* the swept fields' own, whose choices the list flags take */
} bench_renderer_flags;
void bench_renderer_flags_build(bench_renderer_flags *f);
/* A configuration's renderer descriptor at w x h, without the context: the options given
 * (bench_options.base) with every effect off, the configuration's mode, strategy, light format,
 * light scale and Fresnel layout, statistics read every frame. */
tl_renderer_desc bench_config_desc(const bench_options *o, bench_config c, uint32_t w, uint32_t h);

/* One effect in one configuration, at the first size and light count: the configuration rendered
 * with the effect and without it, frame by frame in turn; its error against fat with the same effect. */
typedef struct bench_effect_record {
    bench_effect effect;
    bench_config config;
    uint32_t lights, width, height, frames;
    double effect_ms;              /* median over the frames of the effect's passes' GPU time */
    double frame_ms, base_ms;      /* median frame time with the effect, and without it */
    double ratio;                  /* median over the frames of (with / without, the frames side by side) */
    tl_image_error ldr;            /* final image vs fat with the same effect, RGB, 8-bit steps */
    tl_image_error base_ldr;       /* the same without the effect (what the configuration loses already) */
    tl_image_error ao;             /* SSAO: the AO target vs fat's (peak 1) */
    uint32_t bytes_per_pixel, base_bytes_per_pixel; /* memory the targets occupy, with and without */
} bench_effect_record;

/* One AA method in one mode at the first size and one light count, against the truth of that
 * light count (bench_aa.c). */
typedef struct bench_aa_record {
    bench_aa aa;
    bench_config config;           /* the mode with the first strategy */
    uint32_t samples, lights, width, height, frames;
    double ms_median;              /* frame time (GPU timers, else the wall clock) */
    double ratio_vs_fxaa;          /* median of (this / the same mode's FXAA frame beside it), or of the
                                      medians when they were not rendered side by side; NaN: no FXAA record */
    double ratio_vs_none;          /* the same against the mode's no-AA frame (the 1x frame); NaN: no such record */
    tl_image_error ldr, edge_ldr;  /* final image vs the truth, RGB 8-bit; over the edge pixels alone */
    double edge_fraction;          /* edge pixels over all (the truth's) */
    uint32_t bytes_per_pixel;      /* memory the targets occupy */
    double relit_fraction;         /* thin-lpp with MSAA: tl_frame_stats.relit_fraction; per-sample edges
                                      (msaaNe): tl_frame_stats.msaa_edge_fraction; NaN elsewhere */
} bench_aa_record;

/* The truth of one light count (bench_aa.c): its image and edge mask at the first size. */
typedef struct bench_aa_truth {
    uint32_t lights, width, height;
    uint8_t *rgb;                  /* RGB, rows bottom up */
    uint8_t *edge;                 /* 1 = edge pixel */
    size_t edge_pixels;
    double ms;                     /* the supersampled frame's time */
} bench_aa_truth;

/* One (mode, lights, size): medians over the timed frames, sizes from the plan, errors against the
 * fat image of the same frame. */
typedef struct bench_record {
    bench_config config;
    tl_render_mode mode;           /* bench_config_mode(config) */
    tl_light_strategy strategy;    /* what the plan used (auto resolved to volumes or tiled) */
    int requested;                 /* in --modes (fat may be rendered only as the reference) */
    uint32_t lights;               /* local lights: point + spot */
    uint32_t point_lights, spot_lights, directional_lights;
    uint32_t width, height, frames;
    double ms_median, ms_p90;      /* GPU time of the frame (sum of the pass timers) */
    double *frame_ms;              /* each timed frame's, in order (frames interleaved across modes); may be NULL */
    double wall_ms_median, wall_ms_p90; /* render call to GPU done */
    uint64_t passes;               /* bits BENCH_PASS_BIT(tl_pass) of the plan's passes (33 passes: past 32 bits) */
    double pass_ms[TL_PASS_COUNT]; /* median per pass */
    double pass_bytes[TL_PASS_COUNT];
    uint64_t pass_fragments[TL_PASS_COUNT];
    double bytes_moved;            /* per frame, the renderer's estimate */
    uint32_t target_bpp[TL_TARGET_COUNT]; /* bytes per pixel each allocated target takes */
    uint32_t bytes_per_pixel;      /* memory the targets actually occupy (targets with disjoint
                                      lifetimes share it): the memory figure */
    uint32_t bytes_per_pixel_sum;  /* sum of target_bpp (as if every target had its own memory) */
    double cpu_ms_median;          /* CPU time the render call spends issuing commands */
    uint32_t gbuffer_bytes_per_pixel; /* depth + G-buffer + light buffer */
    uint64_t light_fragments[TL_LIGHT_TYPE_COUNT_];
    uint64_t light_fragment_sum;   /* sum of light_fragments, every type (the directional light's too): the
                                      fragments the light volumes shaded past their range test; 0 for tiles */
    uint64_t covered_pixels;       /* pixels with at least one local light in range (tl_light_pair_count) */
    uint32_t lights_drawn[TL_LIGHT_TYPE_COUNT_];
    uint64_t forward_light_pairs;
    uint32_t draw_calls, objects_drawn;
    uint64_t light_pairs;          /* pixel-light pairs the light pass shaded (tl_frame_stats.light_pairs) */
    double lighting_ms;            /* the passes that apply the lights: light-cull + lights or lights-tiled
                                      (deferred), light-cull + forward, light-cull + vis-resolve */
    /* The roofline (docs/bandwidth.md, "Reading the results"): local lights only, at the grid the light
     * pass shades. */
    int pairs_counted;             /* exact_pairs and covered_pixels were counted (else absent) */
    uint64_t exact_pairs;          /* pixel-light pairs in range (tl_renderer_count_light_pairs) */
    int evaluated_known;           /* 0: forward's per-object lists (not countable per pixel): absent */
    uint64_t evaluated_pairs;      /* what the strategy evaluated: tiled, each list entry over the
                                      pixels of its blocks (light_pairs); volumes, the local lights' fragments past the range test */
    double probe_ns_own;           /* this record's renderer's ALU probe (tl_renderer_light_probe); NaN: none */
    double probe_ns_per_pair;      /* the least probe_ns_own of the run at this size, light count and lighting
                                      model (noise only adds time); NaN: absent */
    double floor_ms;               /* exact_pairs x probe_ns_per_pair; NaN: absent */
    double light_efficiency;       /* floor_ms / lighting_ms; NaN without a lighting time */
    tl_image_error ldr;            /* final image vs fat, RGB in 8-bit steps */
    tl_image_error edge_ldr;       /* the same over the edge pixels alone (bench_edges.c) */
    uint64_t edge_pixels;          /* how many pixels are edge pixels (0: no edge mask) */
    int has_scale1;                /* a light-scale variant: compared with thin-lpp at scale 1 too */
    tl_image_error scale1_ldr;     /* final image vs thin-lpp at light scale 1 (same strategy, frame) */
    tl_image_error edge_scale1_ldr; /* the same over the edge pixels */
    uint64_t relit_pixels;         /* tl_frame_stats.relit_pixels of the last frame */
    double relit_fraction;         /* tl_frame_stats.relit_fraction of the last frame */
    double relit_fraction_marked;  /* HDR pixels the material pass marked re-lit (alpha 0.5) over all (0 with light-upsample) */
    tl_image_error hdr;            /* HDR target vs fat, RGB, peak = fat's largest value */
    double hdr_peak;
    uint64_t nan_pixels;           /* pixels with a NaN or Inf channel in the HDR target */
    tl_lighting_model lighting;    /* the plan's lighting model */
    tl_fresnel_layout fresnel;     /* the plan's Fresnel layout (thin-lpp with GGX), else DEFAULT */
} bench_record;

typedef enum bench_image_kind {
    BENCH_IMAGE_FINAL,         /* a mode's final image */
    BENCH_IMAGE_HEAT,          /* |mode - fat| */
    BENCH_IMAGE_HEAT_DOC,      /* the same, block maxima at most 640 wide, for the doc */
    BENCH_IMAGE_HEAT_SCALE1,   /* light-scale variants: |variant - thin-lpp at scale 1| */
    BENCH_IMAGE_HEAT_SCALE1_DOC,
    BENCH_IMAGE_EDGES,         /* the edge pixels (white) over fat's luma, darkened */
    BENCH_IMAGE_KINDS
} bench_image_kind;
extern const char *const bench_image_kind_names[BENCH_IMAGE_KINDS];

typedef struct bench_image_file {
    char path[512];
    bench_image_kind kind;
    bench_config config;
    uint32_t lights, width, height;
} bench_image_file;

/* An image of the AA measurement: the truth's (aa = BENCH_AAS) or a record's, full size or the doc's
 * crop. */
typedef struct bench_aa_image {
    char path[512];
    bench_config config;
    bench_aa aa;                   /* BENCH_AAS: the truth */
    int crop;
    uint32_t lights;
} bench_aa_image;

/* What planning saves for one mode (the plan against tl_renderer_options.planning off), for the scene
 * with the largest light count. */
typedef struct bench_planning {
    tl_render_mode mode;
    uint32_t bytes_per_pixel, unplanned_bytes_per_pixel;
    size_t programs, unplanned_programs;
    size_t passes, unplanned_passes;
    /* Median frame time (GPU timers, else wall clock) at the first size of a planned renderer and of
     * one with planning off, their frames interleaved; NaN until bench_sweep measures them. */
    double planned_ms, unplanned_ms;
} bench_planning;

typedef struct bench_run {
    bench_options opt;
    tl_tool_log log;               /* the loader's and the renderers' lines, each printed once */
    bench_record *records;         /* size-major, then lights, then modes in render order */
    size_t record_count, record_capacity;
    char gl_renderer[128], gl_version[128];
    char context[16], context_platform[256]; /* tl_context_backend_name, tl_context_platform_string */
    char cpu[128];
    size_t cores;
    char scene_name[256];
    char light_definition[256];    /* what "N lights" means for this scene */
    char shadow_casters[128];      /* --shadows: which of them cast */
    size_t scene_triangles, scene_objects, scene_file_lights;
    double seconds;                /* the whole sweep */
    double load_start, load_end;   /* 1-minute load average before and after it (NaN: unknown) */
    int timers_ok;                 /* GPU timer queries answered (otherwise ms = wall clock) */
    bench_image_file *images;
    size_t image_count, image_capacity;
    int plots_made;
    bench_planning planning[BENCH_MODES];
    size_t planning_count;
    bench_effect_record *effects;  /* --effects: per configuration (fat first), per effect */
    size_t effect_count;
    bench_aa_record *aa;           /* --aa: per light count, per mode, per method */
    size_t aa_count;
    char aa_skipped[BENCH_MODES * BENCH_AAS][160]; /* "mode msaaN: why not" of each method not applied */
    size_t aa_skipped_count;
    bench_aa_image *aa_images;     /* the images of the AA doc (--out) */
    size_t aa_image_count;
    int aa_plot_made;
    struct bench_shadow_record *shadows; /* --shadows: per configuration (bench_shadows.h) */
    size_t shadow_count;
    char shadow_truth_why[160];    /* why the shadows have no truth ("": they have) */
    char shadow_truth_light[64];   /* which light the truth is of */
    int shadow_plot_made;
    /* renderers made once and given each configuration's options and size in turn (bench_renderer) */
    tl_renderer *renderers[BENCH_CONFIGS + 1];
} bench_run;

/* The most memory the renderers held at once may take in copies of the scene (each renderer uploads
 * its own; on llvmpipe they are process memory): as many renderers as fit take turns frame by
 * frame, at least one. */
#define BENCH_SCENE_COPIES_BYTES ((size_t)512 << 20)

/* bench_scene.c: the geometry of the sweep (built-in crypt or glTF file) and its lights for N. */
typedef struct bench_scene bench_scene;
/* 0, or BENCH_EXIT_BAD_INPUT after one line on stderr (an unreadable or invalid scene). */
int bench_scene_open(const bench_options *opt, bench_scene **out, bench_run *run);
const tl_scene *bench_scene_get(const bench_scene *s);
/* The lights of a frame with `n` local lights; the array is owned by the scene until the next call. */
int bench_scene_lights(bench_scene *s, uint32_t n, const tl_light **lights, size_t *count);
/* The same with the crypt's moonlight and braziers casting when `shadows` (a glTF file's lights
 * never cast: --shadows is refused for a file). */
int bench_scene_casting_lights(bench_scene *s, uint32_t n, int shadows, const tl_light **lights, size_t *count);
void bench_scene_close(bench_scene *s);
/* What one renderer's copy of the scene takes, estimated: its textures with their mip chains, its
 * vertices and indices. */
size_t bench_scene_bytes(const bench_scene *s);

/* bench_sweep.c: renders everything and fills run->records (and the images under --out), then
 * times run->planning's modes planned and unplanned (so bench_planning_compare comes first). */
int bench_sweep(bench_run *run, bench_scene *scene);
/* How many renderers with the scene may be held at once: BENCH_SCENE_COPIES_BYTES over
 * bench_scene_bytes, at least 1. */
size_t bench_renderers_at_once(const bench_scene *scene);
/* Fills what every renderer of the bench shares: the context's loader, the log, the budget. */
void bench_renderer_desc(bench_run *run, tl_context *ctx, tl_renderer_desc *d);
/* Renderer `slot` of the run with the size and options of `d` (context, logger and budget are
 * bench_renderer_desc's): made with `scene` the first time the slot is asked for, afterwards given
 * d's options (tl_renderer_set_options) and size, so the scene is uploaded once per slot for the whole
 * run and every renderer keeps its programs. NULL after the log said why. */
tl_renderer *bench_renderer(bench_run *run, tl_context *ctx, size_t slot, tl_renderer_desc d, const tl_scene *scene);
/* Destroys the run's renderers (before its context). */
void bench_renderers_close(bench_run *run);
/* The configurations rendered (at most BENCH_CONFIGS), strategy by strategy: fat first (the
 * reference of the strategy's group), then the requested modes. */
size_t bench_render_modes(const bench_options *opt, bench_config *modes);
/* The index in opt->strategies of the group visibility/tiled is rendered in (bench_sweep.c). */
size_t bench_visibility_group(const bench_options *opt);
int bench_mode_requested(const bench_options *opt, tl_render_mode mode);
/* The record of (configuration, lights, size), or NULL. */
const bench_record *bench_find(const bench_run *run, bench_config config, uint32_t lights, bench_size size);
/* The fat record the error of `config` was measured against (the same strategy). */
bench_config bench_reference_of(bench_config config);

/* Median and 90th percentile (nearest rank) of v[0..n), n > 0; both sort v (bench_sweep.c). */
void bench_median_p90(double *v, size_t n, double *median, double *p90);
double bench_median(double *v, size_t n);

/* Derived figures shared by the table, JSON and doc. */
/* How many times faster `a` is than `b`: the median over the timed frames of b's frame time over
 * a's frame rendered right before or after it (robust to a machine busy with other work), or the
 * ratio of the medians when the frame times are missing. */
double bench_speedup(const bench_record *a, const bench_record *b);
/* The pass that shades with the lights (its light-cull aside): lights + lights-tiled, forward's
 * forward, visibility's vis-resolve (like forward's, it also evaluates the materials). */
double bench_light_pass_ms(tl_render_mode mode, const double *pass_ms);
double bench_per_light_ms(const bench_record *r);          /* lighting_ms / lights; NaN for 0 lights */
double bench_ns_per_pair(const bench_record *r);           /* lighting_ms / light_pairs in ns; NaN when none */
double bench_ms_per_mpixel_covered(const bench_record *r); /* lighting_ms / covered Mpx; NaN when none */
double bench_mib_at(const bench_record *r, uint32_t w, uint32_t h); /* plan bytes at another size */
uint32_t bench_light_buffer_bpp(const bench_record *r);    /* light.diffuse + light.specular + light.fresnel */

/* bench_effects.c: measures opt.effects (at the first size and light count, the configurations of
 * the first strategy); frames it renders, for the progress bar. */
int bench_effects_measure(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress,
                          uint64_t *done);
uint64_t bench_effects_frames(const bench_options *opt);
/* The effect's options from opt.base into `d` (every field of its struct), turned on. */
void bench_effect_enable(const bench_options *opt, bench_effect e, tl_renderer_desc *d);

/* bench_effects_report.c: the effects' table (stdout), JSON member and Markdown table. */
void bench_effects_print_table(const bench_run *run);
void bench_effects_json(tl_tool_json *j, const bench_run *run);
int bench_effects_update_doc(const bench_run *run, const char *doc_text);
#define BENCH_EFFECTS_DOC_BEGIN "<!-- bench-effects:begin -->"
#define BENCH_EFFECTS_DOC_END "<!-- bench-effects:end -->"

/* bench_aa.c: measures opt.aa (at the first size, every light count, the requested modes with the
 * first strategy, against the truth); frames it renders, for the progress bar. */
int bench_aa_measure(bench_run *run, tl_context *ctx, bench_scene *scene, tl_tool_progress *progress, uint64_t *done);
uint64_t bench_aa_frames(const bench_run *run, const bench_scene *scene);
/* Refuses (one line, before any GL work) a truth whose targets are over the target-memory budget. */
int bench_aa_check_budget(const bench_run *run, const bench_scene *scene);
void bench_aa_free(bench_run *run);

/* bench_aa_truth.c (pure: no GL): the tone map of shaders/tonemap.frag.glsl on the CPU. */
/* One channel of linear HDR radiance into linear display [0, 1]: clamped to [0, 65504] (NaN: 0),
 * times the exposure, through the ACES fit (Narkowicz 2015), clamped to [0, 1]. */
float bench_aa_tone(float c, float exposure);
/* Linear display [0, 1] to an 8-bit sRGB step (rounded). */
uint8_t bench_aa_srgb8(float l);
/* The image of a `scale` times wider and taller HDR frame (RGBA floats, rows bottom up, as
 * tl_renderer_read_target gives them) at w x h: each scale x scale block tone-mapped per sample,
 * averaged, sRGB-encoded (RGB, rows bottom up). scale 1: the renderer's tone map with FXAA off. */
void bench_aa_resolve(const float *hdr, uint32_t w, uint32_t h, uint32_t scale, float exposure, uint8_t *rgb);
/* The w x h mask of the pixels whose block of a scale-times-larger mask has a marked sample;
 * returns how many. */
size_t bench_aa_reduce_mask(const uint8_t *fine, uint32_t w, uint32_t h, uint32_t scale, uint8_t *mask);

/* bench_aa_report.c: the AA table (stdout), JSON member and Markdown table (with the plot and crops). */
void bench_aa_print_table(const bench_run *run);
void bench_aa_json(tl_tool_json *j, const bench_run *run);
int bench_aa_update_doc(const bench_run *run, const char *doc_text);
/* bench_aa_images.c: into opt.out, the truth's image (rec NULL) or a record's, full size and the doc's
 * crop; listed in run->aa_images. */
int bench_aa_images(bench_run *run, const bench_aa_truth *truth, const bench_aa_record *rec, const uint8_t *rgb);
/* bench_aa_plot.c: the edge PSNR against the frame time, a panel per light count, into opt.out. */
int bench_aa_plot(bench_run *run);
#define BENCH_AA_PLOT "bench_aa_error_vs_ms"
/* The doc's crops (bench_aa_images.c): BENCH_AA_CROP_W x BENCH_AA_CROP_H pixels (at most the frame)
 * where the truth has the most edge pixels, magnified BENCH_AA_CROP_ZOOM times. */
#define BENCH_AA_CROP_W 160u
#define BENCH_AA_CROP_H 90u
#define BENCH_AA_CROP_ZOOM 3u
#define BENCH_AA_PNG_MAX_BYTES (1024u * 1024u)
#define BENCH_AA_DOC_BEGIN "<!-- bench-aa:begin -->"
#define BENCH_AA_DOC_END "<!-- bench-aa:end -->"
/* --aa-doc's markers: the default pair, or --aa-doc-section's (bench_aa_report.c). */
void bench_aa_doc_markers(const bench_options *o, char *begin, char *end, size_t size);
/* bench_plan.c: fills run->planning for every rendered mode (pure: no GL; the times stay NaN). */
int bench_planning_compare(bench_run *run, bench_scene *scene);

/* bench_images.c: the final image (final_image), the heat map against fat (heat_map) and, with
 * scale1_ldr (light-scale variants), the heat map against thin-lpp at scale 1. RGB, rows bottom up. */
int bench_images_write(bench_run *run, const bench_record *rec, const uint8_t *ldr, const uint8_t *ref_ldr,
                       const uint8_t *scale1_ldr, int final_image, int heat_map);

/* The edge pixels of a size over fat's final image (rec: the fat record), bench_edges_<WxH>.png. */
int bench_images_write_edges(bench_run *run, const bench_record *rec, const uint8_t *ref_ldr, const uint8_t *mask);

/* bench_edges.c: the edge mask (1 = edge pixel) of a frame from fat's DEPTH and FAT_NORMAL targets
 * as tl_renderer_read_target gives them (4 floats a pixel, rows bottom up); returns the edge pixels. */
size_t bench_edges_mask(const float *depth, const float *normal, uint32_t w, uint32_t h, uint8_t *mask);
/* The error of a against b (RGB, 8-bit) over the pixels of `mask` alone. */
void bench_edges_compare(const uint8_t *a, const uint8_t *b, const uint8_t *mask, size_t pixels, tl_image_error *out);
/* The configuration a light-scale variant is compared with: thin-lpp at scale 1, same strategy. */
static inline bench_config bench_config_scale1(bench_config c) { return bench_config_variant(c, 0); }
static inline int bench_config_scaled(bench_config c) { return bench_config_light_scale(c) > 0.0f; }

/* bench_report.c */
void bench_print_table(const bench_run *run);
int bench_write_json(const bench_run *run, const char *path);
/* Replaces the region between the markers in opt.doc; copies the plots into img/ beside it. */
int bench_update_doc(const bench_run *run, const char *doc_text);

/* bench_plot.c: the three plots into opt.out. */
int bench_plots(bench_run *run);
#define BENCH_PLOT_COUNT 3
extern const char *const bench_plot_names[BENCH_PLOT_COUNT];

#endif
