/* Seeded region growing (the robot's ground segmentation: seeded at the bottom middle of the
 * frame, it grows over the floor) and the per-column free space of a region mask (the obstacle
 * boundary the obstacle avoidance steers by).
 *
 * bvb_region_grow: img, width x height 8-bit, img_stride bytes between rows.
 *   The region starts as the seed pixel (p->seed_x, p->seed_y). Pixels are taken from a FIFO
 *   queue in order (breadth first); for a pixel (x, y) taken from the queue its neighbours are
 *   looked at in this order:
 *     (x-1, y), (x+1, y), (x, y-1), (x, y+1)                    (p->connectivity 4 or 8)
 *     then (x-1, y-1), (x+1, y-1), (x-1, y+1), (x+1, y+1)       (8 only)
 *   A neighbour inside the frame and not yet in the region joins it when its intensity I is
 *   within p->tol of the mean of the pixels accepted so far, tested without division as
 *       |I * count - sum| <= tol * count
 *   with count and sum the region's pixel count and intensity sum at that moment (the mean moves
 *   with every pixel accepted). A pixel that joins is marked, counted and appended to the queue.
 *   A pixel that fails stays out, and is tested again, against the mean of that later moment,
 *   each time another of its region neighbours is taken from the queue.
 *   The queue is circular, queue_cap int32 entries (each (y << 16) | x), caller scratch. A pixel
 *   that joins while the queue holds queue_cap entries is still marked and counted but is not
 *   queued (its own neighbours are not looked at from it); stats->dropped counts such pixels.
 *   Each pixel is queued at most once, so queue_cap >= width * height never drops anything; the
 *   result is defined (and deterministic) for every queue_cap >= 0.
 *   A seed outside the frame gives an empty region.
 * Output: mask, width x height, mask_stride bytes between rows: 255 in the region, 0 elsewhere
 *   (every pixel written, row padding untouched), and *stats. Returns stats->count.
 * Limits: 0 <= tol <= 255; width, height >= 1 and width * height * max(width, height) < 2^31
 *   (1280 x 1024 fits), so every sum below fits an int32.
 *
 * bvb_free_space: mask as above (non-zero = free floor, e.g. bvb_region_grow's output).
 *   For each column x, going up from the bottom row, rows[x] is the row where the free floor
 *   stops: the bottom row of the first run of at least min_gap (>= 1) consecutive zero pixels,
 *   where a run that reaches row 0 counts whatever its length (the top of the frame is taken as
 *   an obstacle); -1 when there is no such run (free to the top). With min_gap = 1 it is the
 *   largest y with mask(x, y) == 0, the convention of the scene's column ground truth
 *   (boundary_row). rows: width int16. */
#ifndef BVB_REGION_H
#define BVB_REGION_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct bvb_region_params {
  int32_t seed_x, seed_y;
  int32_t tol;          /* 0..255 */
  int32_t connectivity; /* 4 or 8 */
};

struct bvb_region_stats {
  int32_t count;                    /* pixels in the region */
  int32_t sum;                      /* sum of their intensities: the mean is sum / count */
  int32_t min_x, min_y, max_x, max_y; /* bounding box, inclusive; width, height, -1, -1 if empty */
  int32_t sum_x, sum_y;             /* the centroid is (sum_x / count, sum_y / count) */
  int32_t dropped;                  /* pixels that joined while the queue was full */
};

int32_t bvb_region_grow_c(const uint8_t *img, int32_t img_stride, uint8_t *mask, int32_t mask_stride,
                          int32_t width, int32_t height, const struct bvb_region_params *p,
                          int32_t *queue, int32_t queue_cap, struct bvb_region_stats *stats);
int32_t bvb_region_grow_asm(const uint8_t *img, int32_t img_stride, uint8_t *mask, int32_t mask_stride,
                            int32_t width, int32_t height, const struct bvb_region_params *p,
                            int32_t *queue, int32_t queue_cap, struct bvb_region_stats *stats);

void bvb_free_space_c(const uint8_t *mask, int32_t mask_stride, int32_t width, int32_t height,
                      int32_t min_gap, int16_t *rows);
void bvb_free_space_asm(const uint8_t *mask, int32_t mask_stride, int32_t width, int32_t height,
                        int32_t min_gap, int16_t *rows);

#ifdef __cplusplus
}
#endif

#endif
