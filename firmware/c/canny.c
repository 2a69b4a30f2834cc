#include "bvb/canny.h"

/* States of a pixel in the edge map while the kernel runs. */
#define NOT_EDGE 0
#define WEAK 1

/* A layout hint only: most pixels are below the low threshold, and the simulator charges 9
 * cycles for an unpredicted taken branch. */
#if defined(__GNUC__)
#define BVB_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define BVB_LIKELY(x) (x)
#endif

static void magnitude_row(const int16_t *gx, const int16_t *gy, uint16_t *m, int32_t width) {
  for (int32_t x = 0; x < width; ++x) {
    int32_t a = gx[x], b = gy[x];
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    m[x] = (uint16_t)(a + b);
  }
}

struct stack {
  int32_t *items;
  int32_t cap, top;
  int32_t full; /* a pixel became an edge without being pushed */
};

static void push(struct stack *s, int32_t off) {
  if (s->top < s->cap)
    s->items[s->top++] = off;
  else
    s->full = 1;
}

/* Follows edges from every pixel on the stack: a weak 8-neighbour becomes an edge and is pushed.
 * Only interior pixels are ever pushed, and the ring holds NOT_EDGE, so neighbours stay inside. */
static void drain(struct stack *s, uint8_t *e, int32_t es) {
  const int32_t nb[8] = {-es - 1, -es, -es + 1, -1, 1, es - 1, es, es + 1};
  while (s->top > 0) {
    const int32_t off = s->items[--s->top];
    for (int32_t k = 0; k < 8; ++k) {
      const int32_t n = off + nb[k];
      if (e[n] == WEAK) {
        e[n] = BVB_CANNY_EDGE;
        push(s, n);
      }
    }
  }
}

/* The fallback after the stack filled: every weak pixel next to an edge becomes one. */
static void link_pass(struct stack *s, uint8_t *e, int32_t es, int32_t width, int32_t height) {
  for (int32_t y = 1; y < height - 1; ++y) {
    uint8_t *r = e + y * es;
    for (int32_t x = 1; x < width - 1; ++x) {
      if (r[x] != WEAK) continue;
      const uint8_t *u = r - es, *d = r + es;
      if (u[x - 1] == BVB_CANNY_EDGE || u[x] == BVB_CANNY_EDGE || u[x + 1] == BVB_CANNY_EDGE ||
          r[x - 1] == BVB_CANNY_EDGE || r[x + 1] == BVB_CANNY_EDGE ||
          d[x - 1] == BVB_CANNY_EDGE || d[x] == BVB_CANNY_EDGE || d[x + 1] == BVB_CANNY_EDGE) {
        r[x] = BVB_CANNY_EDGE;
        push(s, y * es + x);
      }
    }
  }
}

int32_t bvb_canny_c(const int16_t *gx, const int16_t *gy, int32_t grad_stride, uint8_t *edges,
                    int32_t edge_stride, int32_t width, int32_t height, int32_t low, int32_t high,
                    uint16_t *mag_rows, int32_t *stack, int32_t stack_cap) {
  if (width < 3 || height < 3) {
    for (int32_t y = 0; y < height; ++y)
      for (int32_t x = 0; x < width; ++x) edges[y * edge_stride + x] = NOT_EDGE;
    return 0;
  }
  struct stack s = {stack, stack_cap, 0, 0};

  /* Rows y-1, y, y+1 of magnitudes rotate through the three scratch rows. */
  uint16_t *mu = mag_rows, *mc = mag_rows + width, *md = mag_rows + 2 * width;
  magnitude_row(gx, gy, mu, width);
  magnitude_row(gx + grad_stride, gy + grad_stride, mc, width);
  for (int32_t x = 0; x < width; ++x) edges[x] = NOT_EDGE;

  for (int32_t y = 1; y < height - 1; ++y) {
    const int16_t *gxr = gx + y * grad_stride, *gyr = gy + y * grad_stride;
    magnitude_row(gxr + grad_stride, gyr + grad_stride, md, width);
    uint8_t *e = edges + y * edge_stride;
    e[0] = NOT_EDGE;
    e[width - 1] = NOT_EDGE;
    for (int32_t x = 1; x < width - 1; ++x) {
      const int32_t m = mc[x];
      uint8_t v = NOT_EDGE;
      if (!BVB_LIKELY(m < low)) {
        const int32_t sx = gxr[x], sy = gyr[x];
        const int32_t ax = sx < 0 ? -sx : sx, ay = sy < 0 ? -sy : sy;
        const int32_t s2 = (ax + ay) * (ax + ay), two_ax2 = 2 * ax * ax;
        int32_t ma, mb;
        if (s2 < two_ax2) {
          ma = mc[x - 1], mb = mc[x + 1];
        } else if (ay > ax && (ay - ax) * (ay - ax) > two_ax2) {
          ma = mu[x], mb = md[x];
        } else if ((sx < 0) == (sy < 0)) {
          ma = mu[x - 1], mb = md[x + 1];
        } else {
          ma = mu[x + 1], mb = md[x - 1];
        }
        if (m > ma && m >= mb) {
          if (m >= high) {
            v = BVB_CANNY_EDGE;
            push(&s, y * edge_stride + x);
          } else {
            v = WEAK;
          }
        }
      }
      e[x] = v;
    }
    uint16_t *t = mu;
    mu = mc;
    mc = md;
    md = t;
  }
  for (int32_t x = 0; x < width; ++x) edges[(height - 1) * edge_stride + x] = NOT_EDGE;

  int32_t passes = 0;
  for (;;) {
    drain(&s, edges, edge_stride);
    if (!s.full) break;
    s.full = 0;
    ++passes;
    link_pass(&s, edges, edge_stride, width, height);
  }

  /* Weak pixels never reached are not edges. */
  for (int32_t y = 1; y < height - 1; ++y) {
    uint8_t *e = edges + y * edge_stride;
    for (int32_t x = 1; x < width - 1; ++x)
      if (e[x] == WEAK) e[x] = NOT_EDGE;
  }
  return passes;
}
