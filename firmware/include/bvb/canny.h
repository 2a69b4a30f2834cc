/* Canny edge detection from Sobel gradients: magnitude, non-maximum suppression, double threshold
 * and hysteresis, giving a one-pixel-thin 8-bit edge map.
 *
 * Input: gx, gy, width x height int16 planes, grad_stride ELEMENTS between rows: the raw 3x3
 * Sobel responses (y down)
 *     Gx = [-1 0 1; -2 0 2; -1 0 1],   Gy = [-1 -2 -1; 0 0 0; 1 2 1],
 * |Gx|, |Gy| <= 1020 and the outer ring 0, as the Sobel kernel writes them. The result below is
 * defined (and exact, with this arithmetic) for any input with |Gx|, |Gy| <= 16383, ring or not.
 *
 * 1. Magnitude: m = |Gx| + |Gy| (L1 norm; 0..2040 for Sobel input), at every pixel (the ring's
 *    magnitudes are neighbours of the interior's).
 * 2. Non-maximum suppression, at interior pixels (1 <= x <= width-2, 1 <= y <= height-2). With
 *    ax = |Gx|, ay = |Gy|, the gradient falls in one of four sectors whose boundaries are exactly
 *    22.5 and 67.5 degrees (tan 22.5 = sqrt2 - 1, tan 67.5 = sqrt2 + 1, squared to integers):
 *      0 deg  (gradient along x):  (ax + ay)^2 < 2 ax^2               [ay < (sqrt2 - 1) ax]
 *      90 deg (gradient along y):  ay > ax and (ay - ax)^2 > 2 ax^2   [ay > (sqrt2 + 1) ax]
 *      else diagonal: 45 deg when Gx and Gy have the same sign, else 135 deg
 *    (no integer pair lies on an irrational boundary, so the rule is the geometric one). The
 *    two neighbours along the gradient, a before b in raster order:
 *      0 deg:   a = (x-1, y),   b = (x+1, y)
 *      90 deg:  a = (x, y-1),   b = (x, y+1)
 *      45 deg:  a = (x-1, y-1), b = (x+1, y+1)
 *      135 deg: a = (x+1, y-1), b = (x-1, y+1)
 *    The pixel is a local maximum when m > m(a) and m >= m(b): of two equal maxima side by side
 *    along the gradient the first in raster order is kept, so a step edge gives one line.
 * 3. Double threshold (1 <= low <= high): a local maximum with m >= high is strong; one with
 *    low <= m < high is weak; everything else is not an edge.
 * 4. Hysteresis: the edges are the strong pixels and every weak pixel 8-connected to a strong
 *    pixel through weak pixels.
 * Output: edges, width x height bytes, edge_stride bytes between rows: 255 edge, 0 not. The outer
 * ring is always 0; frames narrower or lower than 3 pixels are all 0. Row padding is not written.
 *
 * Edge following never recurses: pixels that become edges are pushed on a caller-provided stack
 * (stack, stack_cap int32 entries, each a byte offset into edges) and popped to look at their 8
 * neighbours. A pixel that becomes an edge while the stack is full is not pushed; once the stack
 * has drained, a raster pass turns every weak pixel with an edge neighbour into an edge (pushing
 * it when there is room), and stack draining and raster passes alternate until the stack drains
 * without having been full. The edge map is therefore exact for every stack_cap >= 0 (any stack
 * size gives the same bytes); a small stack only costs time. A stack of
 * BVB_CANNY_STACK_ENTRIES(width, height) entries never fills. Returns the number of raster
 * passes the full stack caused (0 when it never filled).
 *
 * Scratch: mag_rows, 3 * width uint16 (three rolling rows of magnitudes). While the kernel runs,
 * edges holds the intermediate states (1 = weak, not yet linked). Width and height <= 4096.
 * No alignment beyond the element size: gx, gy, mag_rows 2-byte, stack 4-byte aligned. */
#ifndef BVB_CANNY_H
#define BVB_CANNY_H

#include <stdint.h>

#define BVB_CANNY_EDGE 255
#define BVB_CANNY_STACK_ENTRIES(w, h) ((w) > 2 && (h) > 2 ? ((w) - 2) * ((h) - 2) : 0)
#define BVB_CANNY_MAG_ROWS(w) (3 * (w))

#ifdef __cplusplus
extern "C" {
#endif

int32_t bvb_canny_c(const int16_t *gx, const int16_t *gy, int32_t grad_stride, uint8_t *edges,
                    int32_t edge_stride, int32_t width, int32_t height, int32_t low, int32_t high,
                    uint16_t *mag_rows, int32_t *stack, int32_t stack_cap);

#ifdef __cplusplus
}
#endif

#endif
