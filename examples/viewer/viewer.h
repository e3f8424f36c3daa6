/* thinlight-viewer: a GLFW window over the public API (include/thinlight only). The state every
 * part of the viewer shares; main.c owns it, ui.cpp (Dear ImGui) edits its settings. */
#ifndef THINLIGHT_VIEWER_H
#define THINLIGHT_VIEWER_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#include "tool_budget.h"
#include "tool_environment.h"
#include "tool_log.h"

/** What the window shows (view_table in views.c holds the names and what each reads). */
typedef enum vw_view {
    VW_VIEW_FINAL,          /* the output, after FXAA */
    VW_VIEW_NORMALS,        /* decoded view-space normals (RT0; fat: its normal target) */
    VW_VIEW_GLOSS,          /* gloss (RT0 alpha; fat: normal target alpha) */
    VW_VIEW_LUMA,           /* RT1 luma (thin-deferred) */
    VW_VIEW_CHROMA,         /* RT1 raw checkerboard chroma: Cb on even pixels, Cr on odd ones */
    VW_VIEW_ALBEDO,         /* RT1 albedo with the missing chroma rebuilt (fat: its albedo target) */
    VW_VIEW_DEPTH,          /* linear view depth, log scale from near to the farthest pixel */
    VW_VIEW_POSITION,       /* world position rebuilt from depth, over the scene bounds */
    VW_VIEW_LIGHT_DIFFUSE,  /* light buffer diffuse (thin-lpp) */
    VW_VIEW_LIGHT_SPECULAR, /* light buffer specular (exact layout; compact: its alpha) */
    VW_VIEW_TILE_LIGHTS,    /* local lights per tile (tiled strategy) */
    VW_VIEW_HDR,            /* HDR radiance times exposure before the tone curve, clipped at 1 */
    VW_VIEW_BEFORE_FXAA,    /* the tone-mapped image before FXAA */
    VW_VIEW_DIFF_FAT,       /* heat map of |output - fat output| times diff_scale */
    VW_VIEW_AO_RAW,         /* SSAO's estimate before the blur (ao.raw) */
    VW_VIEW_AO,             /* SSAO after the depth-aware blur (ao), what the frame applies */
    VW_VIEW_DOF_COC,        /* depth of field: circle of confusion radius (dof target alpha), heat scale */
    VW_VIEW_SSR,            /* screen-space reflections: the term added to HDR (ssr target) */
    VW_VIEW_BLOOM,          /* bloom: the glow the tone-map pass adds to HDR (bloom target, first level) */
    VW_VIEW_MSAA_EDGES,     /* MSAA in thin-lpp: pixels with a sample re-lit from the lists (its texel another surface's) */
    VW_VIEW_MATERIAL_MODEL, /* each pixel's material model (tl_material_model), one colour per model (material_ids.c) */
    VW_VIEW_SHADOW_ATLAS,   /* the shadow atlas's depth, per view (shadow_views.c) */
    VW_VIEW_SHADOW_CASCADES, /* each pixel's cascade of the casting directional light, over the image */
    VW_VIEW_SHADOW_ONLY,    /* the shadow-only term: the casting lights' visibility weighted by their diffuse light */
    VW_VIEW_VIS_ID,         /* visibility: the id buffer, each (object, triangle) a hashed colour */
    VW_VIEW_VIS_NORMALS,    /* visibility: the normal rebuilt from each pixel's triangle, as vis-resolve does */
    VW_VIEW_COUNT
} vw_view;

/** How the camera moves. */
typedef enum vw_camera_mode { VW_CAMERA_ORBIT, VW_CAMERA_FLY } vw_camera_mode;

typedef struct vw_camera {
    vw_camera_mode mode;
    float target[3];   /* orbit centre */
    float distance;    /* orbit radius */
    float yaw, pitch;  /* radians; the direction from the eye to what it looks at */
    float eye[3];      /* fly position (and the orbit's eye after vw_camera_get) */
    float speed;       /* fly speed, metres per second */
    float fov_y, near_z, far_z;
    tl_camera scene;   /* the scene's camera, given as it is until the camera moves */
    int moved;
} vw_camera;

/** The dynamic light scale (light_scale.c has the rule). */
typedef struct vw_dynamic {
    int on;              /* --dynamic-light-scale, Shift+R, the panel */
    double budget_ms;    /* frame-time budget (--light-budget-ms): over it while moving, 1/4 */
    uint32_t divisor;    /* 0: the chosen scale; 2 or 4: lowered to 1/2 or 1/4 while the camera moves */
    int moving;          /* the camera moved this frame */
    double still_s;      /* seconds of frames without motion since it last moved */
    uint32_t still_frames;
    tl_camera last_cam;  /* the last frame's camera */
    int have_last;
} vw_dynamic;

/** Per-pass GPU times, smoothed (exponential moving average). */
typedef struct vw_timings {
    uint64_t last_frame;
    double pass_ms[TL_PASS_COUNT];
    double gpu_ms;
    double cpu_ms;
    uint64_t covered; /* fragments of the geometry pass (the last valid frame) */
    int valid;
} vw_timings;

typedef struct vw_app {
    /* scene */
    const char *scene_path;          /* NULL: the built-in crypt */
    tl_default_scene_desc crypt;     /* the crypt's lights */
    uint32_t gltf_extra_lights;      /* glTF: seeded point lights added */
    tl_scene *scene;
    tl_light *base_lights;           /* the scene's lights, for animation */
    size_t light_count;
    float center[3], extent;         /* scene bounds: centre and diagonal */
    /* renderers */
    tl_renderer_desc desc;           /* the settings the panel edits (get_proc_address set once) */
    const tl_tool_environment *env;  /* --environment's pixels, set on every renderer made */
    tl_tool_budgets budgets;         /* the memory budgets (the target budget is in desc) */
    tl_tool_log log;                 /* the loader's and the renderers' lines, each printed once */
    tl_renderer *r;                  /* the main one */
    tl_renderer *fat;                /* fat, for the difference view (created on demand) */
    tl_renderer *split;              /* the split view's right half (created on demand) */
    int kept;                        /* r was made with keep_targets = all (a debug view is on) */
    int rebuild;                     /* settings changed: give the renderers their options (vw_apply_settings) */
    int reload;                      /* light count changed: make the scene again */
    uint32_t width, height;          /* framebuffer size */
    /* what is shown */
    vw_view view;
    int grid;                        /* every view as thumbnails */
    int split_on;                    /* left: desc.mode, right: split_mode */
    tl_render_mode split_mode;
    float diff_scale;                /* heat map: full scale = 1 / diff_scale of the 8-bit range */
    int animate;
    double time;                     /* animation clock, seconds */
    int show_panel;
    vw_camera cam;
    /* results of the last frame */
    vw_timings timings;
    tl_frame_plan plan;
    char *plan_text;
    size_t plan_text_size;
    float depth_range[2];            /* the depth view's scale: nearest and farthest covered pixel */
    uint32_t tile_max;               /* the tile view's scale: most lights in one tile */
    char status[160];                /* a line for the panel (the last screenshot, an error) */
    char view_note[96];              /* why a view is empty in this mode */
    uint8_t *image;                  /* the view, RGBA8 bottom-up, width x height */
    size_t image_pixels;
    float *scratch[3];               /* target readback buffers */
    uint8_t *scratch8[2];
    uint32_t *tile_counts;           /* tile view: local lights per tile, read in the frame */
    size_t tile_capacity;
    void *gl;                        /* GL functions beyond 1.1 (views.c) */
    int screenshot_request;          /* a key asked for one */
    /* light scale (thin-lpp): desc.options.light_scale is the one chosen */
    vw_dynamic dyn;
    float applied_scale;             /* the scale the renderers were last given (vw_apply_settings) */
    double last_gpu_ms;              /* GPU time of the last measured frame of r (0: none yet) */
    float last_gpu_scale;            /* the light scale that frame was rendered with */
    uint64_t r_frames;               /* frames r rendered (its tl_frame_stats.frame numbering) */
    const tl_renderer *counted_r;    /* the renderer r_frames counts */
    float frame_scale[16];           /* the scale of r's frame n at [n % 16] */
    /* the material-model view (material_ids.c): its renderer, coded scene, and what they were made for */
    tl_renderer *ids;
    tl_scene *id_scene;
    const tl_scene *ids_of;
    uint32_t ids_width, ids_height;
} vw_app;

/* material_ids.c: the material-model view into out, which holds the final image (its luma shades
 * the models' colours; hdr: scratch of width x height x 4 floats); 0, or 1 when there is no scene
 * or the renderer failed. */
int vw_material_ids(vw_app *app, const tl_camera *cam, float *hdr, uint8_t *out);
void vw_material_ids_free(vw_app *app);

/* shadow_views.c: the shadow views into out (cascades: out holds the final image, whose luma
 * shades the cascades' colours); 0, or 1 with the reason in app->view_note. Whether the current
 * view needs the renderer's shadow-debug pass; a legend's colours; one atlas texel's colour
 * (stored depth d of view v). */
int vw_shadow_atlas(vw_app *app, tl_renderer *r, uint8_t *out);
int vw_shadow_cascades(vw_app *app, tl_renderer *r, uint8_t *out);
int vw_shadow_only(vw_app *app, tl_renderer *r, uint8_t *out);
int vw_shadow_debug_wanted(const vw_app *app);
void vw_cascade_legend_colour(float t, uint8_t rgb[3]);
void vw_atlas_texel(const tl_shadow_view_info *v, float d, uint8_t *px);

/* views.c */
const char *vw_view_name(vw_view v);
int vw_view_from_name(const char *name, vw_view *v);
const char *vw_view_help(vw_view v);
/** Builds app->image for the current view (or the grid, or the split view) from the frame just
 *  rendered; 0 on success. */
int vw_views_build(vw_app *app, const tl_camera *cam);
/** Installs or removes the application passes of the views: the one the tile view reads the light
 *  lists with, and in visibility the one whose read keeps RT0 for the normals and gloss views. */
void vw_views_app_passes(vw_app *app, tl_renderer *r);
int vw_views_init(vw_app *app, void *(*loader)(const char *));
void vw_views_free(vw_app *app);
/** Colour of t in [0,1] on the heat-map scale (black, blue, green, yellow, red, white). */
void vw_heat(float t, uint8_t rgb[3]);
/** Grid of every view: columns and rows (first view top left, row by row). */
#define VW_GRID_COLS 5u
#define VW_GRID_ROWS 6u

/* camera.c */
void vw_camera_from_scene(vw_camera *c, const tl_camera *scene_cam, float extent);
void vw_camera_get(vw_camera *c, tl_camera *out);
void vw_camera_orbit(vw_camera *c, float dx, float dy);
void vw_camera_look(vw_camera *c, float dx, float dy);
void vw_camera_zoom(vw_camera *c, float steps);
void vw_camera_fly(vw_camera *c, const float move[3], float dt);
void vw_camera_set_mode(vw_camera *c, vw_camera_mode mode);

/* light_scale.c */
/** The light scale the renderers get now: the chosen one, or lower while the camera moves. */
float vw_light_scale_used(const vw_app *app);
/** Once a frame, with the frame's camera and time step: updates the dynamic rule; 1 when the scale
 *  to use differs from the one the renderers have (then call vw_apply_settings). */
int vw_light_scale_step(vw_app *app, const tl_camera *cam, float dt);
/** "1", "1/2" or "1/4". */
const char *vw_light_scale_name(float scale);
/** The R key: the chosen scale 1 -> 1/2 -> 1/4 -> 1. */
void vw_light_scale_cycle(vw_app *app);
/** Shift+R: the dynamic light scale on or off. */
void vw_light_scale_toggle_dynamic(vw_app *app);

/* aa.c: antialiasing as one choice (key M, the panel) */
typedef enum vw_aa { VW_AA_NONE, VW_AA_FXAA, VW_AA_MSAA2, VW_AA_MSAA4, VW_AA_MSAA8, VW_AA_COUNT } vw_aa;
vw_aa vw_aa_of(const tl_renderer_options *o);
const char *vw_aa_name(vw_aa a);
/** Sets the options' fxaa and msaa for `a` and asks for a rebuild. */
void vw_aa_set(vw_app *app, vw_aa a);
/** The M key: none -> FXAA -> MSAA 2x -> 4x -> 8x -> none. */
void vw_aa_cycle(vw_app *app);

/* ui.cpp */
int vw_ui_init(void *glfw_window);
void vw_ui_shutdown(void);
/** Starts an ImGui frame, draws the view texture behind it and the panel; returns 1 when a
 *  setting changed. */
void vw_ui_frame(vw_app *app, uint32_t view_texture);
void vw_ui_render(void);
int vw_ui_wants_mouse(void);
int vw_ui_wants_keyboard(void);

#ifdef __cplusplus
}
#endif
#endif
