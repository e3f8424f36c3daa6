/* The material-model view: each pixel coloured by its material's tl_material_model. A renderer of
 * its own draws a copy of the scene whose materials are unlit, coded by model in red, with no
 * lights (forward), from the same camera; its HDR names each pixel's model. Made again when the
 * scene or the size changes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "viewer.h"

/* One colour per model (sRGB8), in tl_material_model order; the sky and unknown codes black. */
static const uint8_t vw_model_colours[TL_MATERIAL_MODEL_COUNT_][3] = {
    {160, 160, 160}, {255, 230, 60}, {60, 140, 255}, {220, 80, 220}, {255, 140, 60}, {60, 220, 110}};

void vw_material_ids_free(vw_app *app)
{
    tl_renderer_destroy(app->ids);
    app->ids = NULL;
    if (app->id_scene) free(app->id_scene->materials);
    free(app->id_scene);
    app->id_scene = NULL;
    app->ids_of = NULL;
}

/* The coded copy: the scene's arrays shared, its own materials and no lights. */
static int vw_material_ids_make(vw_app *app)
{
    const tl_scene *s = app->scene;
    tl_scene *c = calloc(1, sizeof *c);
    size_t n = s->material_count ? s->material_count : 1;
    tl_material *m = calloc(n, sizeof *m);
    if (!c || !m) {
        free(c);
        free(m);
        return 1;
    }
    *c = *s;
    for (size_t i = 0; i < n; i++) {
        uint32_t model = s->material_count ? s->materials[i].model : 0;
        m[i] = (tl_material){.model = TL_MATERIAL_MODEL_UNLIT, .albedo = {(float)(model + 1) / 8.0f, -1, -1}};
        uint32_t kept = TL_MATERIAL_DOUBLE_SIDED | TL_MATERIAL_ALPHA_BLEND; /* what decides the surface drawn */
        if (s->material_count) m[i].flags = s->materials[i].flags & kept;
    }
    c->materials = m;
    c->material_count = s->material_count;
    c->lights = NULL;
    c->light_count = 0;
    c->textures = s->textures;
    app->id_scene = c;
    tl_renderer_desc d = app->desc;
    d.width = app->width;
    d.height = app->height;
    d.options = (tl_renderer_options){.mode = TL_MODE_FORWARD, .keep_targets = TL_TARGET_BIT(TL_TARGET_HDR),
                                      .depth_format = app->desc.options.depth_format};
    if (tl_renderer_create(&d, &app->ids) != TL_OK || tl_renderer_set_scene(app->ids, c) != TL_OK) return 1;
    app->ids_of = s;
    app->ids_width = app->width;
    app->ids_height = app->height;
    return 0;
}

int vw_material_ids(vw_app *app, const tl_camera *cam, float *hdr, uint8_t *out)
{
    if (!app->scene) return 1;
    if (app->ids_of != app->scene || app->ids_width != app->width || app->ids_height != app->height) {
        vw_material_ids_free(app);
        if (vw_material_ids_make(app)) return 1;
    }
    size_t n = (size_t)app->width * app->height, size = n * 16;
    if (tl_renderer_render(app->ids, cam, NULL) != TL_OK ||
        tl_renderer_read_target(app->ids, TL_TARGET_HDR, hdr, &size) != TL_OK)
        return 1;
    for (size_t i = 0; i < n; i++) { /* the model's colour, shaded by the image's luma (in out) */
        long code = lround(hdr[4 * i] * 8.0f);
        uint8_t *p = out + 4 * i;
        float shade = 0.35f + 0.65f * (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f;
        for (int k = 0; k < 3; k++)
            p[k] = code >= 1 && code <= TL_MATERIAL_MODEL_COUNT_ ? (uint8_t)(vw_model_colours[code - 1][k] * shade) : 0;
        p[3] = 255;
    }
    return 0;
}
