#include "bvb/region.h"

#define IN_REGION 255

/* A layout hint only: inside the region most neighbours are in it already, and the simulator
 * charges 9 cycles for an unpredicted taken branch. */
#if defined(__GNUC__)
#define BVB_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define BVB_LIKELY(x) (x)
#endif

/* The growing region: its statistics and the FIFO of pixels whose neighbours are still to be
 * looked at. */
struct grow {
  const uint8_t *img;
  uint8_t *mask;
  int32_t *queue;
  int32_t cap, head, tail, queued, dropped;
  int32_t tol, count, sum, tol_count; /* tol_count = tol * count */
  int32_t sum_x, sum_y, min_x, min_y, max_x, max_y;
};

/* Pixel (x, y), at offset io in img and mo in mask, joins the region if it is not in it yet and
 * |I * count - sum| <= tol * count. */
static inline void visit(struct grow *g, int32_t x, int32_t y, int32_t io, int32_t mo) {
  if (BVB_LIKELY(g->mask[mo] != 0)) return;
  const int32_t i = g->img[io];
  int32_t d = i * g->count - g->sum;
  if (d < 0) d = -d;
  if (d > g->tol_count) return;
  g->mask[mo] = IN_REGION;
  g->count += 1;
  g->sum += i;
  g->tol_count += g->tol;
  g->sum_x += x;
  g->sum_y += y;
  if (x < g->min_x) g->min_x = x;
  if (x > g->max_x) g->max_x = x;
  if (y < g->min_y) g->min_y = y;
  if (y > g->max_y) g->max_y = y;
  if (g->queued < g->cap) {
    g->queue[g->tail] = (y << 16) | x;
    if (++g->tail == g->cap) g->tail = 0;
    g->queued += 1;
  } else {
    g->dropped += 1;
  }
}

int32_t bvb_region_grow_c(const uint8_t *img, int32_t img_stride, uint8_t *mask, int32_t mask_stride,
                          int32_t width, int32_t height, const struct bvb_region_params *p,
                          int32_t *queue, int32_t queue_cap, struct bvb_region_stats *stats) {
  for (int32_t y = 0; y < height; ++y)
    for (int32_t x = 0; x < width; ++x) mask[y * mask_stride + x] = 0;

  struct grow g;
  g.img = img, g.mask = mask, g.queue = queue;
  g.cap = queue_cap, g.head = 0, g.tail = 0, g.queued = 0, g.dropped = 0;
  g.tol = p->tol, g.count = 0, g.sum = 0, g.tol_count = 0;
  g.sum_x = 0, g.sum_y = 0, g.min_x = width, g.min_y = height, g.max_x = -1, g.max_y = -1;
  const int32_t sx = p->seed_x, sy = p->seed_y, eight = p->connectivity == 8;
  const int32_t is = img_stride, ms = mask_stride;

  /* The seed joins unconditionally: against an empty region (count 0, sum 0) the test
   * |I * 0 - 0| <= tol * 0 holds. */
  if (sx >= 0 && sx < width && sy >= 0 && sy < height) visit(&g, sx, sy, sy * is + sx, sy * ms + sx);

  while (g.queued > 0) {
    const int32_t q = g.queue[g.head];
    if (++g.head == g.cap) g.head = 0;
    g.queued -= 1;
    const int32_t x = q & 0xFFFF, y = q >> 16;
    const int32_t io = y * is + x, mo = y * ms + x;
    const int32_t left = x > 0, right = x < width - 1, up = y > 0, down = y < height - 1;
    if (left) visit(&g, x - 1, y, io - 1, mo - 1);
    if (right) visit(&g, x + 1, y, io + 1, mo + 1);
    if (up) visit(&g, x, y - 1, io - is, mo - ms);
    if (down) visit(&g, x, y + 1, io + is, mo + ms);
    if (eight) {
      if (up && left) visit(&g, x - 1, y - 1, io - is - 1, mo - ms - 1);
      if (up && right) visit(&g, x + 1, y - 1, io - is + 1, mo - ms + 1);
      if (down && left) visit(&g, x - 1, y + 1, io + is - 1, mo + ms - 1);
      if (down && right) visit(&g, x + 1, y + 1, io + is + 1, mo + ms + 1);
    }
  }

  stats->count = g.count;
  stats->sum = g.sum;
  stats->min_x = g.min_x;
  stats->min_y = g.min_y;
  stats->max_x = g.max_x;
  stats->max_y = g.max_y;
  stats->sum_x = g.sum_x;
  stats->sum_y = g.sum_y;
  stats->dropped = g.dropped;
  return g.count;
}

void bvb_free_space_c(const uint8_t *mask, int32_t mask_stride, int32_t width, int32_t height,
                      int32_t min_gap, int16_t *rows) {
  for (int32_t x = 0; x < width; ++x) {
    int32_t boundary = -1, gap = 0;
    for (int32_t y = height - 1; y >= 0; --y) {
      if (mask[y * mask_stride + x]) {
        gap = 0;
        continue;
      }
      ++gap;
      if (gap >= min_gap || y == 0) {
        boundary = y + gap - 1;
        break;
      }
    }
    rows[x] = (int16_t)boundary;
  }
}
