/* Tiled light lists (docs/frame.md, "Tiled light accumulation"): the buffers the light-cull pass
 * writes, their growth, the read-back of its counters, and the light-cull pass's CPU side and
 * dispatch. The lists hold as many entries as the buffer has room for; a tile whose list does not
 * fit loops over every visible light instead (no light is lost), the frame's count of entries is
 * read back a few frames later without waiting, and the buffer grows for the frames after. */
#include <string.h>

#include "lights.h"
#include "targets.h"

#define TL__TILE_HEADER_BYTES(lists) (16u + 8u * (size_t)(lists))

/* The light-cull dispatch, (tiles / 8) x (tiles / 8) x chunks, and the tiled shading's (side / 8)^2
 * stay within GL's guaranteed GL_MAX_COMPUTE_WORK_GROUP_COUNT of 65535 per dimension: a 16384-pixel
 * side (8-pixel tiles) and TL_RENDERER_MAX_LIGHTS lights in chunks of TL__CULL_CHUNK. */
_Static_assert((TL_RENDERER_MAX_LIGHTS + TL__CULL_CHUNK - 1) / TL__CULL_CHUNK <= 65535, "light-cull chunks");
_Static_assert((16384 + 7) / 8 <= 65535, "compute groups across a side");

static size_t tl__tile_count(const tl__tiles *t) { return (size_t)t->x * t->y; }

void tl__tiles_release(tl__device *dev, tl__tiles *t)
{
    const GladGLContext *gl = &dev->gl;
    for (int i = 0; i < TL__QUERY_RING; i++)
        if (t->fences[i]) gl->DeleteSync(t->fences[i]);
    GLuint buffers[3] = {t->headers, t->entries, t->readback};
    for (int i = 0; i < 3; i++)
        if (buffers[i]) gl->DeleteBuffers(1, &buffers[i]);
    memset(t, 0, sizeof *t);
}

static tl_result tl__tiles_entries(tl__device *dev, tl__tiles *t, size_t capacity)
{
    const GladGLContext *gl = &dev->gl;
    if (t->entries) gl->DeleteBuffers(1, &t->entries); /* queued frames keep what they read */
    gl->CreateBuffers(1, &t->entries);
    gl->NamedBufferStorage(t->entries, (GLsizeiptr)(capacity * sizeof(uint32_t)), NULL, 0);
    tl__gl_label(gl, GL_BUFFER, t->entries, "buffer.tiles.entries");
    t->capacity = capacity;
    return TL_OK;
}

/* The headers: counters, then (first entry, count) per tile for each of `chunks` light chunks. One
 * storage block: TL_ERROR_LIMIT past it (a huge frame with many lights in view). */
static tl_result tl__tiles_headers(tl__device *dev, tl__tiles *t, uint32_t chunks)
{
    const GladGLContext *gl = &dev->gl;
    size_t bytes = TL__TILE_HEADER_BYTES(tl__tile_count(t) * chunks);
    if (bytes > dev->lim.storage_max)
        return tl__fail(dev, TL_ERROR_LIMIT,
                        "renderer: tiled light lists of %ux%u tiles for %u chunks of %u lights need %zu bytes, over the "
                        "storage block of %zu bytes", t->x, t->y, chunks, TL__CULL_CHUNK, bytes, dev->lim.storage_max);
    if (t->headers) gl->DeleteBuffers(1, &t->headers); /* queued frames keep what they read */
    gl->CreateBuffers(1, &t->headers);
    gl->NamedBufferStorage(t->headers, (GLsizeiptr)bytes, NULL, GL_DYNAMIC_STORAGE_BIT);
    tl__gl_label(gl, GL_BUFFER, t->headers, "buffer.tiles.headers");
    t->chunks = chunks;
    return TL_OK;
}

tl_result tl__tiles_configure(tl__device *dev, tl__tiles *t, uint32_t size, uint32_t x, uint32_t y)
{
    if (t->headers && t->size == size && t->x == x && t->y == y) return TL_OK; /* the same tiles: kept, grown */
    const GladGLContext *gl = &dev->gl;
    tl__tiles_release(dev, t);
    t->size = size;
    t->x = x;
    t->y = y;
    tl_result res = tl__tiles_headers(dev, t, 1);
    if (res != TL_OK) return res;
    const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    gl->CreateBuffers(1, &t->readback);
    gl->NamedBufferStorage(t->readback, TL__QUERY_RING * 16, NULL, flags);
    t->readback_map = (const uint32_t *)gl->MapNamedBufferRange(t->readback, 0, TL__QUERY_RING * 16, flags);
    tl__gl_label(gl, GL_BUFFER, t->readback, "buffer.tiles.readback");
    if (!t->readback_map) return tl__fail(dev, TL_ERROR_GL, "renderer: could not map the tile counters' read-back");
    size_t max_entries = dev->lim.storage_max / sizeof(uint32_t), capacity = tl__tile_count(t) * TL__TILE_START_ENTRIES;
    return tl__tiles_entries(dev, t, capacity < max_entries ? capacity : max_entries);
}

/* Counters of `frame` once the GPU has finished it: 1 with them in out[4], 0 when not (yet). */
static int tl__tiles_counters(tl__device *dev, tl__tiles *t, uint64_t frame, int wait, uint32_t out[4])
{
    unsigned s = (unsigned)(frame % TL__QUERY_RING);
    if (!t->readback_map || t->fence_frame[s] != frame || !t->fences[s]) return 0;
    GLenum w = dev->gl.ClientWaitSync(t->fences[s], wait ? GL_SYNC_FLUSH_COMMANDS_BIT : 0, wait ? 1000000000u : 0);
    if (w != GL_ALREADY_SIGNALED && w != GL_CONDITION_SATISFIED) return 0;
    memcpy(out, t->readback_map + 4 * s, 4 * sizeof(uint32_t));
    return 1;
}

/* Grows the entries buffer when a finished frame needed more than it holds (checked each frame,
 * for the frames of the ring that have finished: no waiting). */
static tl_result tl__tiles_grow(tl__device *dev, tl__lights *l, uint64_t frame)
{
    tl__tiles *t = &l->tiles;
    for (uint64_t f = frame > TL__QUERY_RING ? frame - TL__QUERY_RING : 1; f < frame; f++) {
        uint32_t c[4];
        if (tl__tiles_counters(dev, t, f, 0, c) && c[0] > t->needed) t->needed = c[0];
    }
    size_t local = l->view_count - l->view_dir_count;
    t->frame_chunks = local > TL__CULL_CHUNK ? (uint32_t)((local + TL__CULL_CHUNK - 1) / TL__CULL_CHUNK) : 1u;
    if (t->frame_chunks > t->chunks) {
        tl_result res = tl__tiles_headers(dev, t, t->frame_chunks);
        if (res != TL_OK) return res;
    }
    /* the entries are one storage block: they grow up to it; past it, the tiles whose lists do not
     * fit loop over every light of their chunk (a documented clamp: slower, nothing lost) */
    size_t max_entries = dev->lim.storage_max / sizeof(uint32_t);
    if (t->needed <= t->capacity || t->capacity >= max_entries) return TL_OK;
    size_t cap = t->capacity;
    while (cap < t->needed + t->needed / 2 && cap < max_entries) cap *= 2;
    if (cap > max_entries) {
        cap = max_entries;
        tl__log_message(&dev->log, TL_LOG_WARNING,
                "renderer: tiled light lists need %zu entries; the storage block holds %zu: tiles that do not fit "
                "loop over every light", t->needed, max_entries);
    }
    return tl__tiles_entries(dev, t, cap);
}

tl_result tl__tiles_prepare(tl__device *dev, tl__lights *l, uint64_t frame, tl_frame_stats *st)
{
    for (size_t i = 0; i < l->view_count; i++) /* the lights that reach the view, per type */
        st->lights_drawn[(int)l->view[i].color_type[3]]++;
    return tl__tiles_grow(dev, l, frame);
}

void tl__tiles_upload(tl__device *dev, tl__lights *l)
{
    tl__stream_bind_buffer(&dev->gl, &dev->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_TILE_HEADERS, l->tiles.headers);
    tl__stream_bind_buffer(&dev->gl, &dev->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_TILE_ENTRIES, l->tiles.entries);
}

/* The light-cull pass: counters cleared, one invocation per tile, the counters copied for the
 * read-back behind a fence. */
void tl__tiles_cull(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    tl__tiles *t = &ctx->lights->tiles;
    gl->ClearNamedBufferSubData(t->headers, GL_R32UI, 0, 16, GL_RED_INTEGER, GL_UNSIGNED_INT, NULL);
    gl->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    tl__state_program(gl, ctx->state, ctx->programs[0]);
    gl->DispatchCompute((t->x + 7) / 8, (t->y + 7) / 8, t->frame_chunks);
    gl->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    unsigned s = (unsigned)(ctx->frame % TL__QUERY_RING);
    gl->CopyNamedBufferSubData(t->headers, t->readback, 0, (GLintptr)(16 * s), 16);
    if (t->fences[s]) gl->DeleteSync(t->fences[s]);
    t->fences[s] = gl->FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    t->fence_frame[s] = ctx->frame;
}

void tl__tiles_collect(tl__device *dev, tl__tiles *t, tl_frame_stats *st)
{
    uint32_t c[4];
    if (!tl__tiles_counters(dev, t, st->frame, 1, c)) return;
    st->light_list_entries = c[0];
    st->tile_overflows = c[1];
    /* none counted: the lists served light-upsample alone (volumes at a light scale), whose light
     * pass counted its own pairs */
    if (c[2] | c[3]) st->light_pairs = ((uint64_t)c[3] << 32) | c[2];
}
