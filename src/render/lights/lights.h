/* The lights module: the scene's lights (validated copies), the light-volume meshes and each
 * frame's instances by type (light_volumes.c), the frame's visible lights in view space
 * (light_lists.c), the forward per-object light lists (forward_lists.c) and the tiled light lists'
 * buffers (tiles.c). A frame asks for what its passes declared (TL__LIGHTS_*): prepare on the CPU,
 * then upload into the frame's stream. */
#ifndef TL_RENDER_LIGHTS_H
#define TL_RENDER_LIGHTS_H

#include "pass.h"
#include "view.h"

enum { TL__LIGHT_KINDS = 3 }; /* point, spot, directional: index = type - 1 */
#define TL__QUERY_RING 4      /* frames whose queries and tile counters may be in flight */

/* One light as every pass reads it (tl_light_data, light_eval.glsl): a record of the lights storage
 * block (view space) or a light volume's instance (light.vert attributes 1..4, world space). One
 * function packs it (tl__light_record_fill), so a light's new factor is one line there and one in
 * tl_light_data_weights. */
typedef struct tl__light_record {
    float position_radius[4];
    float color_type[4];          /* linear colour, type (1 point, 2 spot, 3 directional) */
    float direction_cos_outer[4];
    float cos_inner[4];           /* spot cos_inner, source radius, shadow slot (0: none), specular scale */
} tl__light_record;

/* Tiled light lists (tiles.c): four counters (entries used, tiles that overflowed, shaded pairs as
 * two 32-bit halves) then (offset, count) per tile; the entries; and a ring of read-back copies of
 * the counters, read once their fence has passed (never waited for in a frame). */
typedef struct tl__tiles {
    GLuint headers, entries;
    size_t capacity;            /* entries the buffer holds */
    size_t needed;              /* most entries a finished frame used (read back) */
    uint32_t size, x, y;        /* tile side in pixels, tiles across and down */
    uint32_t chunks;            /* light chunks (TL__CULL_CHUNK) the headers hold lists for */
    uint32_t frame_chunks;      /* chunks this frame's visible local lights make */
    GLuint readback;
    const uint32_t *readback_map;  /* TL__QUERY_RING x 4 counters */
    GLsync fences[TL__QUERY_RING];
    uint64_t fence_frame[TL__QUERY_RING];
} tl__tiles;

/* The light scale's fix-up count (fixup.c): one storage buffer of four counters (the fourth: every
 * pixel or sample the material pass re-lit) and a ring of read-back copies, as the tiles'. */
typedef struct tl__fixup {
    GLuint buffer;
    GLuint readback;
    const uint32_t *readback_map;  /* TL__QUERY_RING x 4 counters */
    GLsync fences[TL__QUERY_RING];
    uint64_t fence_frame[TL__QUERY_RING];
} tl__fixup;

/* Visibility's material buckets (pass_visibility.c): one storage buffer, made again when a plan needs
 * more tiles; vis-classify fills it, vis-resolve dispatches from it. */
typedef struct tl__vis_tiles {
    GLuint buffer;
    size_t bytes;
} tl__vis_tiles;

struct tl__lights {
    tl_light *lights;
    size_t count;
    size_t allocated;           /* lights the five per-light arrays hold (reused while enough) */
    size_t kinds[TL__LIGHT_KINDS]; /* lights per type */
    /* volumes (light_volumes.c) */
    tl__light_record *instances;  /* per frame: the visible lights by type, outside volumes first */
    size_t instance_base[TL__LIGHT_KINDS], instance_count[TL__LIGHT_KINDS], instance_outside[TL__LIGHT_KINDS];
    int fullscreen;           /* this frame's point and spot lights are full-screen triangles */
    GLuint vao[TL__LIGHT_KINDS];
    GLuint vbo_volume[2], ibo_volume[2];
    uint32_t volume_index_count[2];
    /* the frame's visible lights in view space, directional ones first (light_lists.c) */
    tl__light_record *view;
    uint32_t *view_index;      /* scene light index of each */
    float (*view_spheres)[4];  /* world-space bounding sphere of each; radius < 0: reaches everything */
    size_t view_count, view_dir_count;
    size_t view_cast_end;      /* local lights with a shadow slot come first: [view_dir_count, view_cast_end) */
    /* forward per-object lists (forward_lists.c) */
    uint32_t *fwd_indices;
    size_t fwd_capacity, fwd_count;
    uint32_t *fwd_first, *fwd_object_count; /* per object */
    size_t fwd_objects;                     /* objects the two arrays hold */
    /* tiled light lists (tiles.c) */
    tl__tiles tiles;
    /* the light scale's fix-up list (fixup.c) */
    tl__fixup fixup;
    /* visibility's material buckets (pass_visibility.c) */
    tl__vis_tiles vis;
    /* per scene light: its shadow slot (shadow.glsl) for this frame, 0: none; NULL without shadows
     * (owned by the shadow module, shadows.c) */
    const float *shadow_slots;
};

/* lights.c: a light's record, world space (view: NULL) or in the view's space (its 4x4 matrix,
 * column-major), with its shadow slot. */
void tl__light_record_fill(const tl_light *l, const float *view, float shadow_slot, tl__light_record *out);

/* lights.c: validated copies of the lights (with per-frame scratch for them), counted by type;
 * TL_ERROR_LIMIT past the device's light limit, before the array is read. */
tl_result tl__lights_count_check(tl__device *dev, size_t count);
tl_result tl__lights_store(tl__device *dev, tl__lights *l, const tl_light *lights, size_t count);
/* Scratch for `objects` per-object lists (a new scene). */
tl_result tl__lights_objects(tl__device *dev, tl__lights *l, size_t objects);
void tl__lights_release(tl__device *dev, tl__lights *l);
/* The frame's light data the plan needs (`needs`: TL__LIGHTS_*), on the CPU; adds what it will
 * upload to *stream_bytes; fills the per-type counts of the statistics. */
tl_result tl__lights_prepare(tl__device *dev, tl__lights *l, const tl__scene_gpu *scene, const tl__view *v,
                             unsigned needs, int fullscreen, uint64_t frame, tl_frame_stats *st, size_t *stream_bytes);
/* Into the frame's stream, bound where the shaders read it. */
void tl__lights_upload(tl__device *dev, tl__lights *l, unsigned needs);
/* The frame block's light counts (visible directional, visible local) and tile layout. */
void tl__lights_frame_block(const tl__lights *l, unsigned needs, uint32_t counts[3], uint32_t tiles[4]);

/* light_volumes.c */
void tl__light_volumes_create(tl__device *dev, tl__lights *l);
void tl__light_volumes_destroy(tl__device *dev, tl__lights *l);
void tl__volumes_prepare(tl__lights *l, const tl__view *v, tl_frame_stats *st, size_t *stream_bytes);
void tl__volumes_upload(tl__device *dev, tl__lights *l);

/* light_lists.c: the frame's visible lights in view space. */
void tl__light_sphere(const tl_light *l, float c[3], float *radius);
void tl__visible_lights(tl__device *dev, tl__lights *l, const tl__view *v, size_t *stream_bytes);
void tl__visible_lights_upload(tl__device *dev, tl__lights *l);

/* forward_lists.c: per-object light lists of the visible lights (forward and transparent); empty
 * ones unless `per_object` (Forward+ alone reads tile lists). */
tl_result tl__forward_prepare(tl__device *dev, tl__lights *l, const tl__scene_gpu *scene, int per_object,
                              tl_frame_stats *st, size_t *stream_bytes);
void tl__forward_upload(tl__device *dev, tl__lights *l);

/* tiles.c: the tiled light lists' buffers for a plan's tiles (made again only when they change),
 * their growth and read-back, and the light-cull pass's dispatch. */
tl_result tl__tiles_configure(tl__device *dev, tl__tiles *t, uint32_t size, uint32_t x, uint32_t y);
void tl__tiles_release(tl__device *dev, tl__tiles *t);
tl_result tl__tiles_prepare(tl__device *dev, tl__lights *l, uint64_t frame, tl_frame_stats *st);
void tl__tiles_upload(tl__device *dev, tl__lights *l);
void tl__tiles_cull(const tl__pass_ctx *ctx);
/* The counters of `frame` (waiting for its fence) into the statistics. */
void tl__tiles_collect(tl__device *dev, tl__tiles *t, tl_frame_stats *st);

/* fixup.c: the counters' buffer (made once); before the material pass they are cleared, after it
 * they are copied for the read-back. */
tl_result tl__fixup_configure(tl__device *dev, tl__fixup *f);
void tl__fixup_release(tl__device *dev, tl__fixup *f);
void tl__fixup_bind(tl__device *dev, tl__fixup *f);
void tl__fixup_begin(const GladGLContext *gl, tl__fixup *f);
void tl__fixup_end(const GladGLContext *gl, tl__fixup *f, uint64_t frame);
/* The re-lit count of `frame` (waiting for its fence) into the statistics. */
void tl__fixup_collect(tl__device *dev, tl__fixup *f, uint32_t pixels, tl_frame_stats *st);

/* lights.c: the storage targets the lights module owns (the tile lists, the re-lit count): the GL
 * buffer an application pass is given for one (0 for other targets), and the counters of the
 * frame in the statistics for those a plan has (`targets`). */
GLuint tl__lights_buffer(const tl__lights *l, tl_target_id t);
void tl__lights_read_counters(tl__device *dev, tl__lights *l, tl_target_set targets, uint32_t pixels,
                              tl_frame_stats *st);

#endif
