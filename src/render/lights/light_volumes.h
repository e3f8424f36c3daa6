/* Light-volume meshes (private). */
#ifndef TL_RENDER_LIGHT_VOLUMES_H
#define TL_RENDER_LIGHT_VOLUMES_H

#include <stdint.h>

#define TL__SPHERE_SEGMENTS 12u
#define TL__SPHERE_RINGS 8u
#define TL__CONE_SEGMENTS 12u
#define TL__VOLUME_MAX_VERTICES 128u
#define TL__VOLUME_MAX_INDICES 600u

typedef struct tl__volume_mesh {
    float vertices[TL__VOLUME_MAX_VERTICES * 3];
    uint32_t indices[TL__VOLUME_MAX_INDICES];
    uint32_t vertex_count, index_count;
} tl__volume_mesh;

void tl__sphere_volume(tl__volume_mesh *m);
void tl__cone_volume(tl__volume_mesh *m);

#endif
