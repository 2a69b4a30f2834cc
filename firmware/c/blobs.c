#include "bvb/blobs.h"

#define NO_CLASS 0xFF

/* A layout hint only (the simulator charges 9 cycles for an unpredicted taken branch). */
#if defined(__GNUC__)
#define BVB_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define BVB_LIKELY(x) (x)
#endif

struct run {
  int32_t start, end, cls, label; /* label -1: left out (label table full) */
};

struct label {
  int32_t parent, cls, count, min_x, min_y, max_x, max_y, sum_x, sum_y;
};

static int32_t find(struct label *l, int32_t a) {
  while (l[a].parent != a) {
    l[a].parent = l[l[a].parent].parent;
    a = l[a].parent;
  }
  return a;
}

/* Merges roots a != b; the smaller label (the blob met first) stays root, so its min_y, the
 * row it was created on, is already the merged blob's. */
static int32_t unite(struct label *l, int32_t a, int32_t b) {
  const int32_t r = a < b ? a : b, o = a < b ? b : a;
  struct label *R = &l[r], *O = &l[o];
  R->count += O->count;
  R->sum_x += O->sum_x;
  R->sum_y += O->sum_y;
  if (O->min_x < R->min_x) R->min_x = O->min_x;
  if (O->max_x > R->max_x) R->max_x = O->max_x;
  if (O->max_y > R->max_y) R->max_y = O->max_y;
  O->parent = r;
  return r;
}

static void build_luts(const struct bvb_blob_params *p, int32_t nclasses, uint8_t *lut_y,
                       uint8_t *lut_u, uint8_t *lut_v, uint8_t *lowbit) {
  for (int32_t v = 0; v < 256; ++v) {
    uint8_t my = 0, mu = 0, mv = 0;
    for (int32_t c = 0; c < nclasses; ++c) {
      const struct bvb_blob_class *k = &p->cls[c];
      if (v >= k->y_min && v <= k->y_max) my |= (uint8_t)(1u << c);
      if (v >= k->u_min && v <= k->u_max) mu |= (uint8_t)(1u << c);
      if (v >= k->v_min && v <= k->v_max) mv |= (uint8_t)(1u << c);
    }
    lut_y[v] = my, lut_u[v] = mu, lut_v[v] = mv;
    uint8_t b = NO_CLASS;
    for (int32_t c = 7; c >= 0; --c)
      if (v & (1 << c)) b = (uint8_t)c;
    lowbit[v] = b;
  }
}

int32_t bvb_blobs_uyvy_c(const uint8_t *uyvy, int32_t stride, int32_t width, int32_t height,
                         const struct bvb_blob_params *p, struct bvb_blob *blobs,
                         struct bvb_blob_summary *summary, void *scratch, int32_t label_cap) {
  int32_t nclasses = p->nclasses;
  if (nclasses < 0) nclasses = 0;
  if (nclasses > BVB_BLOBS_MAX_CLASSES) nclasses = BVB_BLOBS_MAX_CLASSES;
  const int32_t adj = p->connectivity == 8 ? 1 : 0;
  const int32_t max_blobs = p->max_blobs, min_count = p->min_count;

  uint8_t *lut_y = (uint8_t *)scratch, *lut_u = lut_y + 256, *lut_v = lut_y + 512, *lowbit = lut_y + 768;
  struct run *prev = (struct run *)(lut_y + 1024), *cur = prev + width;
  struct label *labels = (struct label *)(cur + width);
  build_luts(p, nclasses, lut_y, lut_u, lut_v, lowbit);

  int32_t nprev = 0, used = 0, dropped = 0;
  for (int32_t y = 0; y < height; ++y) {
    /* Runs of this row. */
    const uint8_t *row = uyvy + y * stride;
    int32_t ncur = 0, run_cls = NO_CLASS, run_start = 0;
    for (int32_t x = 0; x < width; x += 2, row += 4) {
      const uint8_t uv = lut_u[row[0]] & lut_v[row[2]];
      const int32_t c0 = lowbit[lut_y[row[1]] & uv], c1 = lowbit[lut_y[row[3]] & uv];
      /* Most pairs continue the run (or the stretch of no class) they are in. */
      if (BVB_LIKELY(((c0 ^ run_cls) | (c1 ^ run_cls)) == 0)) continue;
      if (c0 != run_cls) {
        if (run_cls != NO_CLASS) {
          cur[ncur].start = run_start, cur[ncur].end = x - 1, cur[ncur].cls = run_cls;
          ++ncur;
        }
        run_cls = c0, run_start = x;
      }
      if (c1 != run_cls) {
        if (run_cls != NO_CLASS) {
          cur[ncur].start = run_start, cur[ncur].end = x, cur[ncur].cls = run_cls;
          ++ncur;
        }
        run_cls = c1, run_start = x + 1;
      }
    }
    if (run_cls != NO_CLASS) {
      cur[ncur].start = run_start, cur[ncur].end = width - 1, cur[ncur].cls = run_cls;
      ++ncur;
    }

    /* Connect them to the runs above: both lists are sorted by column, so one sweep does. */
    int32_t j = 0;
    for (int32_t i = 0; i < ncur; ++i) {
      struct run *r = &cur[i];
      while (j < nprev && prev[j].end + adj < r->start) ++j;
      int32_t lab = -1;
      for (int32_t k = j; k < nprev && prev[k].start <= r->end + adj; ++k) {
        if (prev[k].cls != r->cls || prev[k].label < 0) continue;
        const int32_t root = find(labels, prev[k].label);
        if (lab < 0)
          lab = root;
        else if (root != lab)
          lab = unite(labels, lab, root);
      }
      const int32_t len = r->end - r->start + 1;
      if (lab < 0) {
        if (used == label_cap) {
          dropped += len;
          r->label = -1;
          continue;
        }
        lab = used++;
        struct label *L = &labels[lab];
        L->parent = lab, L->cls = r->cls, L->count = 0, L->sum_x = 0, L->sum_y = 0;
        L->min_x = r->start, L->max_x = r->end, L->min_y = y, L->max_y = y;
      }
      struct label *L = &labels[lab];
      L->count += len;
      L->sum_x += ((r->start + r->end) * len) >> 1;
      L->sum_y += y * len;
      if (r->start < L->min_x) L->min_x = r->start;
      if (r->end > L->max_x) L->max_x = r->end;
      L->max_y = y;
      r->label = lab;
    }
    struct run *t = prev;
    prev = cur;
    cur = t;
    nprev = ncur;
  }

  /* The largest blobs of each class. Roots are visited in label order, which is the raster
   * order of their first pixels, and an insertion only passes strictly smaller blobs, so equal
   * counts keep that order. */
  int32_t listed[BVB_BLOBS_MAX_CLASSES];
  for (int32_t c = 0; c < BVB_BLOBS_MAX_CLASSES; ++c) listed[c] = 0, summary->found[c] = 0;
  for (int32_t i = 0; i < nclasses * max_blobs; ++i) {
    struct bvb_blob *b = &blobs[i];
    b->cls = b->count = b->min_x = b->min_y = b->max_x = b->max_y = b->sum_x = b->sum_y = 0;
  }
  int32_t total = 0;
  for (int32_t l = 0; l < used; ++l) {
    const struct label *L = &labels[l];
    if (L->parent != l || L->count < min_count) continue;
    const int32_t c = L->cls;
    ++summary->found[c];
    ++total;
    if (max_blobs < 1) continue;
    struct bvb_blob *list = blobs + c * max_blobs;
    const int32_t n = listed[c];
    int32_t pos = n;
    while (pos > 0 && list[pos - 1].count < L->count) --pos;
    if (pos >= max_blobs) continue;
    for (int32_t k = n < max_blobs ? n : max_blobs - 1; k > pos; --k) list[k] = list[k - 1];
    struct bvb_blob *b = &list[pos];
    b->cls = c, b->count = L->count;
    b->min_x = L->min_x, b->min_y = L->min_y, b->max_x = L->max_x, b->max_y = L->max_y;
    b->sum_x = L->sum_x, b->sum_y = L->sum_y;
    if (n < max_blobs) listed[c] = n + 1;
  }
  summary->labels_used = used;
  summary->dropped = dropped;
  return total;
}
