/* Frame statistics without waiting (stats.c): each measured frame's timer and samples-passed
 * queries go into a slot of a small ring, with a copy of what reading them needs of the plan (so
 * the plan may change while frames are in flight), and are read when they are ready. */
#ifndef TL_RENDER_STATS_H
#define TL_RENDER_STATS_H

#include "graph.h"
#include "lights.h"

/* What the CPU knows about a frame (the GPU's figures arrive with its queries). */
typedef struct tl__frame_record {
    tl_frame_stats st;
    size_t indices[TL_PLAN_MAX_PASSES];   /* scene indices drawn per pass (vertex fetch) */
    size_t instances[TL_PLAN_MAX_PASSES]; /* light instances drawn per pass */
    size_t stream_bytes;                  /* per-frame data the prepare steps will upload */
} tl__frame_record;

/* The part of a plan a slot's results are read against. */
typedef struct tl__slot_plan {
    size_t pass_count;
    const tl__pass_def *def[TL_PLAN_MAX_PASSES];
    int8_t app[TL_PLAN_MAX_PASSES];
    tl__pass_decl decl[TL_PLAN_MAX_PASSES];
    uint32_t target_bytes_per_pixel[TL_TARGET_COUNT];
    uint32_t width, height, vertex_attributes;
    tl_target_set targets; /* the plan's targets: its storage targets' counters are read too */
} tl__slot_plan;

typedef struct tl__query_slot {
    GLuint time[TL_PLAN_MAX_PASSES][2];
    GLuint samples[TL_PLAN_MAX_PASSES][TL__PASS_MAX_QUERIES];
    int pending;
    tl__frame_record rec;
    tl__slot_plan plan;
} tl__query_slot;

typedef struct tl__queries {
    tl__query_slot ring[TL__QUERY_RING];
    int timestamps;        /* GL_TIMESTAMP queries work in this context */
    GLint timestamp_bits;
    tl__lights *lights;    /* whose storage targets' counters complete a frame's figures */
} tl__queries;

void tl__queries_create(tl__device *dev, tl__queries *q, tl__lights *lights);
void tl__queries_destroy(tl__device *dev, tl__queries *q);
/* The ring slot for `frame`, read first (blocking) if it still holds an unread frame; it takes the
 * graph's plan for the frame about to be issued. */
tl__query_slot *tl__queries_slot(tl__device *dev, tl__queries *q, const tl__graph *g, uint64_t frame);
/* Reads every slot whose results are ready; the newest read frame's statistics in *out (0: none). */
int tl__queries_newest(tl__device *dev, tl__queries *q, tl_frame_stats *out);
/* Reads every pending slot, waiting for the GPU (when the caller waits). */
void tl__queries_drain(tl__device *dev, tl__queries *q);

#endif
