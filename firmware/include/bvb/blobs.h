/* Colour blob detection on the camera's UYVY frames: pixels are classified into up to 8 colour
 * classes by per-channel ranges, connected into blobs per class, and the largest blobs of each
 * class are reported with pixel count, bounding box and centroid sums.
 *
 * Input: uyvy, width x height pixels in the SRV-1 camera's 4:2:2 byte order U Y0 V Y1: pixel 2k
 *   of a row is (Y0, U, V), pixel 2k+1 is (Y1, U, V). stride: bytes between rows (>= 2 * width).
 *   width even, >= 2; height >= 1; width * height * max(width, height) < 2^31 (1280 x 1024 fits).
 * Classes (struct bvb_blob_params): class c (0 <= c < nclasses <= 8) holds a pixel when
 *   y_min <= Y <= y_max, u_min <= U <= u_max and v_min <= V <= v_max (inclusive; an empty range
 *   holds nothing). Classes may overlap: a pixel belongs to the lowest-numbered class that holds
 *   it, or to none.
 * Blobs: the connected components of the pixels of one class, 4- or 8-connected
 *   (p->connectivity). Pixels of different classes never connect.
 * Output: for each class c < nclasses, blobs[c * max_blobs + i], i < max_blobs: that class's
 *   blobs with count >= min_count, largest first; equal counts in the raster order of their
 *   first pixel (the first pixel met scanning rows top to bottom, each left to right). Unused
 *   slots are all zero (count 0). summary->found[c]: how many blobs of class c had
 *   count >= min_count (may exceed max_blobs); 0 for c >= nclasses. Returns the sum of found.
 *
 * Method: one pass over runs (maximal horizontal stretches of one class in a row). A run that
 * touches runs of its class in the row above (overlapping columns for 4-connectivity, or
 * columns within one for 8) joins their labels, merged by union-find with the smaller label as
 * root; a run that touches none takes a new label. Each label keeps its blob's statistics, merged
 * into the root on union, so no second pass over pixels is needed.
 * The label table holds label_cap labels (caller scratch). A run that needs a new label when
 * the table is full is left out: its pixels count in no blob and connect nothing;
 * summary->dropped counts them. summary->labels_used says how many labels were taken; every
 * label starts at a run, so a table of width * height labels never fills.
 * Scratch: BVB_BLOBS_SCRATCH_BYTES(width, label_cap) bytes, 4-byte aligned.
 * blobs, summary, p: 4-byte aligned. */
#ifndef BVB_BLOBS_H
#define BVB_BLOBS_H

#include <stdint.h>

#define BVB_BLOBS_MAX_CLASSES 8
/* Lookup tables (4 x 256 bytes), two rows of runs (4 int32 each, at most width runs a row) and
 * the label table (9 int32 a label). */
#define BVB_BLOBS_SCRATCH_BYTES(width, label_cap) (1024 + 2 * 16 * (width) + 36 * (label_cap))

#ifdef __cplusplus
extern "C" {
#endif

struct bvb_blob_class {
  int32_t y_min, y_max, u_min, u_max, v_min, v_max;
};

struct bvb_blob_params {
  int32_t nclasses;     /* 1..8 */
  int32_t connectivity; /* 4 or 8 */
  int32_t max_blobs;    /* per class, >= 1 */
  int32_t min_count;    /* smaller blobs are not reported, >= 1 */
  struct bvb_blob_class cls[BVB_BLOBS_MAX_CLASSES];
};

struct bvb_blob {
  int32_t cls;   /* colour class */
  int32_t count; /* pixels */
  int32_t min_x, min_y, max_x, max_y; /* bounding box, inclusive */
  int32_t sum_x, sum_y; /* the centroid is (sum_x / count, sum_y / count) */
};

struct bvb_blob_summary {
  int32_t found[BVB_BLOBS_MAX_CLASSES];
  int32_t labels_used;
  int32_t dropped; /* pixels left out because the label table was full */
};

int32_t bvb_blobs_uyvy_c(const uint8_t *uyvy, int32_t stride, int32_t width, int32_t height,
                         const struct bvb_blob_params *p, struct bvb_blob *blobs,
                         struct bvb_blob_summary *summary, void *scratch, int32_t label_cap);

#ifdef __cplusplus
}
#endif

#endif
