#include "bvb/region.h"

#define IN_REGION 255

int32_t bvb_region_grow_c(const uint8_t *img, int32_t img_stride, uint8_t *mask, int32_t mask_stride,
                          int32_t width, int32_t height, const struct bvb_region_params *p,
                          int32_t *queue, int32_t queue_cap, struct bvb_region_stats *stats) {
  for (int32_t y = 0; y < height; ++y)
    for (int32_t x = 0; x < width; ++x) mask[y * mask_stride + x] = 0;

  int32_t count = 0, sum = 0, sum_x = 0, sum_y = 0, dropped = 0;
  int32_t min_x = width, min_y = height, max_x = -1, max_y = -1;
  const int32_t sx = p->seed_x, sy = p->seed_y, tol = p->tol;
  const int32_t nneigh = p->connectivity == 8 ? 8 : 4;
  static const int8_t ndx[8] = {-1, 1, 0, 0, -1, 1, -1, 1};
  static const int8_t ndy[8] = {0, 0, -1, 1, -1, -1, 1, 1};

  int32_t head = 0, tail = 0, queued = 0;
  if (sx >= 0 && sx < width && sy >= 0 && sy < height) {
    const int32_t i = img[sy * img_stride + sx];
    mask[sy * mask_stride + sx] = IN_REGION;
    count = 1, sum = i, sum_x = sx, sum_y = sy;
    min_x = max_x = sx, min_y = max_y = sy;
    if (queue_cap > 0) {
      queue[0] = (sy << 16) | sx;
      tail = queue_cap > 1 ? 1 : 0;
      queued = 1;
    } else {
      dropped = 1;
    }
  }

  while (queued > 0) {
    const int32_t q = queue[head];
    if (++head == queue_cap) head = 0;
    --queued;
    const int32_t x = q & 0xFFFF, y = q >> 16;
    for (int32_t k = 0; k < nneigh; ++k) {
      const int32_t nx = x + ndx[k], ny = y + ndy[k];
      if (nx < 0 || nx >= width || ny < 0 || ny >= height) continue;
      uint8_t *mp = &mask[ny * mask_stride + nx];
      if (*mp) continue;
      const int32_t i = img[ny * img_stride + nx];
      int32_t d = i * count - sum;
      if (d < 0) d = -d;
      if (d > tol * count) continue;
      *mp = IN_REGION;
      ++count;
      sum += i;
      sum_x += nx;
      sum_y += ny;
      if (nx < min_x) min_x = nx;
      if (nx > max_x) max_x = nx;
      if (ny < min_y) min_y = ny;
      if (ny > max_y) max_y = ny;
      if (queued < queue_cap) {
        queue[tail] = (ny << 16) | nx;
        if (++tail == queue_cap) tail = 0;
        ++queued;
      } else {
        ++dropped;
      }
    }
  }

  stats->count = count;
  stats->sum = sum;
  stats->min_x = min_x;
  stats->min_y = min_y;
  stats->max_x = max_x;
  stats->max_y = max_y;
  stats->sum_x = sum_x;
  stats->sum_y = sum_y;
  stats->dropped = dropped;
  return count;
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
