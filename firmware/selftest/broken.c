/* Broken twins of bvb_add_sat_u8_asm whose defect is easiest to state in C. */
#include "bvb/add_sat.h"
#include "bvb/harris.h"

void bvb_broken_wrong_pixel(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t w, int32_t h,
                            int32_t ss, int32_t ds, void *scr) {
  bvb_add_sat_u8_asm(a, b, dst, w, h, ss, ds, scr);
  dst[(h / 2) * ds + w / 2] ^= 0x10;
}

void bvb_broken_write_past_end(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t w,
                               int32_t h, int32_t ss, int32_t ds, void *scr) {
  bvb_add_sat_u8_asm(a, b, dst, w, h, ss, ds, scr);
  dst[(h - 1) * ds + w] = 0;
}

void bvb_broken_write_before_start(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t w,
                                   int32_t h, int32_t ss, int32_t ds, void *scr) {
  bvb_add_sat_u8_asm(a, b, dst, w, h, ss, ds, scr);
  dst[-1] = 0;
}

void bvb_broken_write_input(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t w, int32_t h,
                            int32_t ss, int32_t ds, void *scr) {
  bvb_add_sat_u8_asm(a, b, dst, w, h, ss, ds, scr);
  ((uint8_t *)a)[0] ^= 1;
}

/* Leaves the last pixel unwritten. */
void bvb_broken_skip_pixel(const uint8_t *a, const uint8_t *b, uint8_t *dst, int32_t w, int32_t h,
                           int32_t ss, int32_t ds, void *scr) {
  if (h > 1) bvb_add_sat_u8_asm(a, b, dst, w, h - 1, ss, ds, scr);
  if (w > 1) bvb_add_sat_u8_asm(a + (h - 1) * ss, b + (h - 1) * ss, dst + (h - 1) * ds, w - 1, 1, ss, ds, scr);
}

/* harris_select writing its in/out candidates after the reference's work: the heap it leaves
 * differs in the first candidate's R. */
int32_t bvb_broken_write_inout(int32_t *cand, int32_t n, int32_t max_corners, int32_t min_distance,
                               int32_t *corners) {
  int32_t taken = bvb_harris_select_c(cand, n, max_corners, min_distance, corners);
  cand[1] ^= 1;
  return taken;
}
