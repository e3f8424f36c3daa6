/* Scale legends drawn into a view's pixels, so that screenshots carry them (legend.c). */
#ifndef THINLIGHT_VIEWER_LEGEND_H
#define THINLIGHT_VIEWER_LEGEND_H

#include <stdint.h>

/* Bar width in pixels at scale 1; a character's advance (5 columns and a space). */
#define VW_LEGEND_BAR_W 128u
#define VW_GLYPH_ADVANCE 6u

typedef struct vw_legend {
    const char *title;                    /* above the bar */
    char low[32], high[32];               /* below its left and right ends */
    void (*colour)(float t, uint8_t rgb[3]); /* the view's mapping of t in [0, 1] */
} vw_legend;

/* Where the legend goes in a w x h image, in pixels from the top left: the box at the bottom
 * left, 8 (x scale) pixels from the edges; the bar's first column is colour(0), its last
 * colour(1). scale is 2 from 960 pixels across, else 1. */
typedef struct vw_legend_box {
    uint32_t scale, x, y, box_w, box_h, pad, bar_x, bar_y, bar_w, bar_h;
} vw_legend_box;

void vw_legend_geometry(uint32_t w, uint32_t h, vw_legend_box *b);
/* Draws the legend into an RGBA8 image whose rows run bottom to top. */
void vw_draw_legend(uint8_t *img, uint32_t w, uint32_t h, const vw_legend *l);
void vw_draw_text(uint8_t *img, uint32_t w, uint32_t h, uint32_t x, uint32_t y, uint32_t scale, const char *s);
uint32_t vw_text_width(const char *s, uint32_t scale);

#endif
