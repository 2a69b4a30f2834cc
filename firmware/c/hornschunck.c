/* Horn-Schunck optical flow, fixed-point C reference. Formats, bounds and the assembly plan are in
 * bvb/hornschunck.h. Each helper below is one Blackfin operation, so the assembly is bit-exact by
 * doing the same operations in the same grouping. */
#include "bvb/hornschunck.h"

/* Entry j - 256 (j = 256..1023) is round(2^29 / sqrt((j + 1/2) * 2^20)): 2^29 / sqrt(Dn) at the
 * middle of the interval of normalised denominators Dn in [2^28, 2^30) whose bits 29..20 are j.
 * Relative error of the reciprocal square root: below 0.985e-3. */
const int16_t bvb_hs_rsqrt_table[BVB_HS_RSQRT_ENTRIES] = {
    32736, 32672, 32609, 32546, 32484, 32422, 32360, 32298, 32237, 32176, 32116, 32056,
    31996, 31937, 31878, 31819, 31760, 31702, 31645, 31587, 31530, 31473, 31416, 31360,
    31304, 31249, 31193, 31138, 31083, 31029, 30975, 30921, 30867, 30814, 30761, 30708,
    30655, 30603, 30551, 30499, 30448, 30397, 30346, 30295, 30245, 30194, 30144, 30095,
    30045, 29996, 29947, 29898, 29850, 29802, 29754, 29706, 29658, 29611, 29564, 29517,
    29470, 29424, 29378, 29332, 29286, 29240, 29195, 29150, 29105, 29060, 29015, 28971,
    28927, 28883, 28839, 28796, 28752, 28709, 28666, 28624, 28581, 28539, 28496, 28454,
    28413, 28371, 28330, 28288, 28247, 28206, 28166, 28125, 28085, 28044, 28004, 27965,
    27925, 27885, 27846, 27807, 27768, 27729, 27690, 27652, 27613, 27575, 27537, 27499,
    27461, 27424, 27386, 27349, 27312, 27275, 27238, 27201, 27165, 27128, 27092, 27056,
    27020, 26984, 26949, 26913, 26878, 26842, 26807, 26772, 26738, 26703, 26668, 26634,
    26600, 26565, 26531, 26497, 26464, 26430, 26397, 26363, 26330, 26297, 26264, 26231,
    26198, 26165, 26133, 26100, 26068, 26036, 26004, 25972, 25940, 25909, 25877, 25846,
    25814, 25783, 25752, 25721, 25690, 25659, 25628, 25598, 25567, 25537, 25507, 25477,
    25447, 25417, 25387, 25357, 25328, 25298, 25269, 25239, 25210, 25181, 25152, 25123,
    25094, 25066, 25037, 25009, 24980, 24952, 24924, 24896, 24868, 24840, 24812, 24784,
    24756, 24729, 24701, 24674, 24647, 24620, 24593, 24566, 24539, 24512, 24485, 24458,
    24432, 24405, 24379, 24353, 24326, 24300, 24274, 24248, 24222, 24196, 24171, 24145,
    24120, 24094, 24069, 24043, 24018, 23993, 23968, 23943, 23918, 23893, 23868, 23844,
    23819, 23794, 23770, 23746, 23721, 23697, 23673, 23649, 23625, 23601, 23577, 23553,
    23529, 23506, 23482, 23459, 23435, 23412, 23388, 23365, 23342, 23319, 23296, 23273,
    23250, 23227, 23204, 23182, 23159, 23137, 23114, 23092, 23069, 23047, 23025, 23003,
    22981, 22958, 22936, 22915, 22893, 22871, 22849, 22828, 22806, 22784, 22763, 22741,
    22720, 22699, 22678, 22656, 22635, 22614, 22593, 22572, 22551, 22530, 22510, 22489,
    22468, 22448, 22427, 22407, 22386, 22366, 22346, 22325, 22305, 22285, 22265, 22245,
    22225, 22205, 22185, 22165, 22145, 22126, 22106, 22086, 22067, 22047, 22028, 22008,
    21989, 21970, 21950, 21931, 21912, 21893, 21874, 21855, 21836, 21817, 21798, 21779,
    21760, 21742, 21723, 21704, 21686, 21667, 21649, 21630, 21612, 21594, 21575, 21557,
    21539, 21521, 21503, 21485, 21467, 21449, 21431, 21413, 21395, 21377, 21360, 21342,
    21324, 21307, 21289, 21271, 21254, 21237, 21219, 21202, 21184, 21167, 21150, 21133,
    21116, 21098, 21081, 21064, 21047, 21030, 21014, 20997, 20980, 20963, 20946, 20930,
    20913, 20896, 20880, 20863, 20847, 20830, 20814, 20798, 20781, 20765, 20749, 20732,
    20716, 20700, 20684, 20668, 20652, 20636, 20620, 20604, 20588, 20572, 20556, 20541,
    20525, 20509, 20493, 20478, 20462, 20447, 20431, 20416, 20400, 20385, 20369, 20354,
    20339, 20323, 20308, 20293, 20278, 20263, 20247, 20232, 20217, 20202, 20187, 20172,
    20157, 20143, 20128, 20113, 20098, 20083, 20069, 20054, 20039, 20025, 20010, 19996,
    19981, 19967, 19952, 19938, 19923, 19909, 19895, 19880, 19866, 19852, 19837, 19823,
    19809, 19795, 19781, 19767, 19753, 19739, 19725, 19711, 19697, 19683, 19669, 19655,
    19642, 19628, 19614, 19600, 19587, 19573, 19559, 19546, 19532, 19519, 19505, 19492,
    19478, 19465, 19451, 19438, 19425, 19411, 19398, 19385, 19372, 19358, 19345, 19332,
    19319, 19306, 19293, 19280, 19267, 19254, 19241, 19228, 19215, 19202, 19189, 19176,
    19163, 19151, 19138, 19125, 19112, 19100, 19087, 19074, 19062, 19049, 19037, 19024,
    19012, 18999, 18987, 18974, 18962, 18949, 18937, 18925, 18912, 18900, 18888, 18876,
    18863, 18851, 18839, 18827, 18815, 18803, 18791, 18779, 18767, 18754, 18743, 18731,
    18719, 18707, 18695, 18683, 18671, 18659, 18647, 18636, 18624, 18612, 18600, 18589,
    18577, 18565, 18554, 18542, 18531, 18519, 18507, 18496, 18484, 18473, 18462, 18450,
    18439, 18427, 18416, 18405, 18393, 18382, 18371, 18359, 18348, 18337, 18326, 18315,
    18303, 18292, 18281, 18270, 18259, 18248, 18237, 18226, 18215, 18204, 18193, 18182,
    18171, 18160, 18149, 18138, 18127, 18117, 18106, 18095, 18084, 18074, 18063, 18052,
    18041, 18031, 18020, 18009, 17999, 17988, 17978, 17967, 17957, 17946, 17936, 17925,
    17915, 17904, 17894, 17883, 17873, 17863, 17852, 17842, 17831, 17821, 17811, 17801,
    17790, 17780, 17770, 17760, 17750, 17739, 17729, 17719, 17709, 17699, 17689, 17679,
    17669, 17659, 17649, 17639, 17629, 17619, 17609, 17599, 17589, 17579, 17569, 17559,
    17550, 17540, 17530, 17520, 17510, 17501, 17491, 17481, 17471, 17462, 17452, 17442,
    17433, 17423, 17413, 17404, 17394, 17385, 17375, 17366, 17356, 17347, 17337, 17328,
    17318, 17309, 17299, 17290, 17281, 17271, 17262, 17252, 17243, 17234, 17225, 17215,
    17206, 17197, 17187, 17178, 17169, 17160, 17151, 17141, 17132, 17123, 17114, 17105,
    17096, 17087, 17078, 17069, 17060, 17051, 17042, 17033, 17024, 17015, 17006, 16997,
    16988, 16979, 16970, 16961, 16952, 16943, 16935, 16926, 16917, 16908, 16899, 16891,
    16882, 16873, 16864, 16856, 16847, 16838, 16830, 16821, 16812, 16804, 16795, 16786,
    16778, 16769, 16761, 16752, 16743, 16735, 16726, 16718, 16709, 16701, 16692, 16684,
    16676, 16667, 16659, 16650, 16642, 16634, 16625, 16617, 16609, 16600, 16592, 16584,
    16575, 16567, 16559, 16551, 16542, 16534, 16526, 16518, 16509, 16501, 16493, 16485,
    16477, 16469, 16461, 16452, 16444, 16436, 16428, 16420, 16412, 16404, 16396, 16388,
};

static inline int32_t sat16(int32_t x) { return x > 32767 ? 32767 : (x < -32768 ? -32768 : x); }

/* x / 2^s rounded to nearest, ties to even: how the MAC unit rounds an accumulator into a half
 * register with RND_MOD = 0 (the reset state; the GNU simulator always rounds this way).
 * 1 <= s <= 30. */
static inline int32_t round_even(int32_t x, int32_t s) {
  int32_t q = x >> s; /* floor: right shifts of negative int32 are arithmetic on both compilers */
  uint32_t r = (uint32_t)x & ((1u << s) - 1u);
  uint32_t half = 1u << (s - 1);
  if (r > half || (r == half && (q & 1))) ++q;
  return q;
}

/* Signed fractional 16 x 16 product as the multiplier forms it: 2ab. -1 * -1 (0x8000 squared)
 * would leave int32, but no call here can produce it (|bar| <= 16384; S and the weights are
 * positive); the guard keeps the helper total. */
static inline int32_t mul_frac(int32_t a, int32_t b) {
  if (a == -32768 && b == -32768) return 0x7fffffff;
  return 2 * a * b;
}

/* a * b in (S2RND) mode extracted to a half register: round(2ab / 2^15), saturated. */
static inline int32_t mult_s2rnd(int32_t a, int32_t b) {
  return sat16(round_even(mul_frac(a, b), 15));
}

/* One half of a saturating dual 16-bit add, R = R +|+ R (S). */
static inline int32_t add_s(int32_t a, int32_t b) { return sat16(a + b); }

static int32_t clamp_alpha2(int32_t a) {
  return a < BVB_HS_ALPHA2_Q4_MIN ? BVB_HS_ALPHA2_Q4_MIN
                                  : (a > BVB_HS_ALPHA2_Q4_MAX ? BVB_HS_ALPHA2_Q4_MAX : a);
}

void bvb_hs_coefficients_c(int32_t gx, int32_t gy, int32_t gt, int32_t alpha2_q4,
                           int16_t *out) {
  const int32_t d = clamp_alpha2(alpha2_q4) + gx * gx + gy * gy;
  int32_t dn = d, k = 0, tn, s;
  /* Even normalisation, Dn = D * 4^k in [2^28, 2^30): then |gx| * 2^k < sqrt(Dn) < 2^15. */
  while (dn < (1 << 28)) {
    dn *= 4;
    ++k;
  }
  s = bvb_hs_rsqrt_table[(dn >> 20) - 256];
  /* g * 2^k * S ~= g / sqrt(D) * 2^29; S2RND takes it to Q15. */
  out[0] = (int16_t)mult_s2rnd(gx * (1 << k), s);
  out[1] = (int16_t)mult_s2rnd(gy * (1 << k), s);
  /* gt can exceed sqrt(D), so it is shifted 5 bits less and lands in Q10. k >= 4 because
   * D < 2^22; k = 4 drops gt's lowest bit (only where D >= 2^20). */
  tn = k >= 5 ? gt * (1 << (k - 5)) : (gt >> (5 - k));
  out[2] = (int16_t)mult_s2rnd(tn, s);
}

void bvb_hs_prepare_c(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height,
                      int32_t stride, int32_t alpha2_q4, int16_t *coef, void *scratch) {
  (void)scratch; /* the assembly's band buffers */
  const int32_t pitch = BVB_HS_COEF_PITCH(width);
  for (int32_t y = 0; y < height; ++y) {
    const int32_t y1 = y + 1 < height ? y + 1 : height - 1;
    const uint8_t *a0 = i1 + y * stride, *a1 = i1 + y1 * stride;
    const uint8_t *b0 = i2 + y * stride, *b1 = i2 + y1 * stride;
    int16_t *g = coef + y * pitch;
    int16_t *t = g + 2 * width;
    for (int32_t x = 0; x < width; ++x) {
      const int32_t x1 = x + 1 < width ? x + 1 : width - 1;
      /* Sums of the four first differences over the 2x2x2 cube: 4 Ex, 4 Ey, 4 Et. */
      const int32_t gx =
          (a0[x1] - a0[x]) + (a1[x1] - a1[x]) + (b0[x1] - b0[x]) + (b1[x1] - b1[x]);
      const int32_t gy =
          (a1[x] - a0[x]) + (a1[x1] - a0[x1]) + (b1[x] - b0[x]) + (b1[x1] - b0[x1]);
      const int32_t gt =
          (b0[x] - a0[x]) + (b0[x1] - a0[x1]) + (b1[x] - a1[x]) + (b1[x1] - a1[x1]);
      int16_t c[3];
      bvb_hs_coefficients_c(gx, gy, gt, alpha2_q4, c);
      g[2 * x] = c[0];
      g[2 * x + 1] = c[1];
      t[x] = c[2];
    }
    if (width & 1) t[width] = 0;
  }
}

/* One output pixel. l, m, r: offsets (int16 units; u even, v odd) of the left, own and right
 * neighbours, already clamped to the row. */
static inline void iterate_pixel(const int16_t *top, const int16_t *mid, const int16_t *bot,
                                 int32_t l, int32_t m, int32_t r, const int16_t *g, int32_t gt,
                                 int16_t *out) {
  const int32_t gx = g[0], gy = g[1];
  /* The 2-sums are saturating dual adds; the four MACs accumulate exactly, |acc| <= 2^30. */
  const int32_t acc_u = mul_frac(add_s(top[l], bot[l]), BVB_HS_W12) +
                        mul_frac(add_s(top[r], bot[r]), BVB_HS_W12) +
                        mul_frac(add_s(mid[l], mid[r]), BVB_HS_W6) +
                        mul_frac(add_s(top[m], bot[m]), BVB_HS_W6);
  const int32_t acc_v = mul_frac(add_s(top[l + 1], bot[l + 1]), BVB_HS_W12) +
                        mul_frac(add_s(top[r + 1], bot[r + 1]), BVB_HS_W12) +
                        mul_frac(add_s(mid[l + 1], mid[r + 1]), BVB_HS_W6) +
                        mul_frac(add_s(top[m + 1], bot[m + 1]), BVB_HS_W6);
  const int32_t ubar = sat16(round_even(acc_u, 16)), vbar = sat16(round_even(acc_v, 16));
  const int32_t e = add_s(add_s(mult_s2rnd(ubar, gx), mult_s2rnd(vbar, gy)), gt);
  /* Integer (IH) products taken off the exact sums, one rounding: |acc - e g| <= 2^31 - 2^16. */
  out[0] = (int16_t)sat16(round_even(acc_u - e * gx, 16));
  out[1] = (int16_t)sat16(round_even(acc_v - e * gy, 16));
}

/* One output row from the input rows above (top), at (mid) and below (bot), clamped. */
static void iterate_row(const int16_t *top, const int16_t *mid, const int16_t *bot,
                        const int16_t *g, int16_t *out, int32_t width) {
  const int16_t *t = g + 2 * width;
  const int32_t last = 2 * (width - 1);
  iterate_pixel(top, mid, bot, 0, 0, width > 1 ? 2 : 0, g, t[0], out);
  for (int32_t x = 1; x < width - 1; ++x)
    iterate_pixel(top, mid, bot, 2 * x - 2, 2 * x, 2 * x + 2, g + 2 * x, t[x], out + 2 * x);
  if (width > 1) iterate_pixel(top, mid, bot, last - 2, last, last, g + last, t[width - 1], out + last);
}

void bvb_hs_iterate_c(const int16_t *coef, const int16_t *uv_in, int32_t in_stride,
                      int16_t *uv_out, int32_t out_stride, int32_t width, int32_t height,
                      void *flow_scratch, void *coef_scratch) {
  const int32_t pitch = BVB_HS_COEF_PITCH(width);
  (void)flow_scratch; /* the assembly's streamed path */
  (void)coef_scratch;
  for (int32_t y = 0; y < height; ++y) {
    const int32_t ym = y > 0 ? y - 1 : 0, yp = y + 1 < height ? y + 1 : height - 1;
    const int16_t *top = (const int16_t *)((const uint8_t *)uv_in + ym * in_stride);
    const int16_t *mid = (const int16_t *)((const uint8_t *)uv_in + y * in_stride);
    const int16_t *bot = (const int16_t *)((const uint8_t *)uv_in + yp * in_stride);
    int16_t *out = (int16_t *)((uint8_t *)uv_out + y * out_stride);
    iterate_row(top, mid, bot, coef + y * pitch, out, width);
  }
}

/* The definition: `iterations` Jacobi iterations one after the other, each exactly
 * bvb_hs_iterate_c. The first goes uv_in -> uv_out; each later one is done in place in uv_out,
 * with copies of the input rows it overwrites (row y - 1 and row y, in two rows of the flow
 * scratch) taken before the output row replaces them, so every output pixel still reads the
 * previous iteration's field. */
void bvb_hs_iterate_n_c(const int16_t *coef, const int16_t *uv_in, int32_t in_stride,
                        int16_t *uv_out, int32_t out_stride, int32_t width, int32_t height,
                        int32_t iterations, void *flow_scratch, void *coef_scratch) {
  (void)coef_scratch; /* the assembly's coefficient rows */
  const int32_t pitch = BVB_HS_COEF_PITCH(width);
  int16_t *saved[2];
  saved[0] = (int16_t *)flow_scratch;
  saved[1] = saved[0] + 2 * width;
  if (iterations < 1) return;
  bvb_hs_iterate_c(coef, uv_in, in_stride, uv_out, out_stride, width, height, 0, 0);
  for (int32_t n = 1; n < iterations; ++n) {
    int16_t *above = saved[0], *here = saved[1];
    for (int32_t x = 0; x < 2 * width; ++x) here[x] = uv_out[x];
    for (int32_t y = 0; y < height; ++y) {
      int16_t *row = (int16_t *)((uint8_t *)uv_out + y * out_stride);
      const int16_t *below = y + 1 < height ? (const int16_t *)((uint8_t *)row + out_stride) : here;
      int16_t *spare;
      iterate_row(y > 0 ? above : here, here, below, coef + y * pitch, row, width);
      /* here (row y's input) becomes the row above; row y + 1's input is copied before the
       * next output row overwrites it */
      spare = above;
      above = here;
      here = spare;
      if (y + 1 < height)
        for (int32_t x = 0; x < 2 * width; ++x) here[x] = below[x];
    }
  }
}

/* Prepare, then the iterations fused by bvb_hs_iterate_n_c from zero flow: one zero row in
 * scratch after the coefficients, read with stride 0 as every row of the start field. */
void bvb_hornschunck_c(const uint8_t *i1, const uint8_t *i2, int32_t width, int32_t height,
                       int32_t stride, int32_t alpha2_q4, int32_t iterations, int16_t *uv_out,
                       int32_t out_stride, void *scratch, void *flow_scratch, void *coef_scratch) {
  int16_t *coef = (int16_t *)scratch;
  int16_t *zero = (int16_t *)((uint8_t *)scratch + BVB_HS_COEF_BYTES(width, height));
  if (iterations < 1) {
    for (int32_t y = 0; y < height; ++y) {
      int16_t *row = (int16_t *)((uint8_t *)uv_out + y * out_stride);
      for (int32_t x = 0; x < 2 * width; ++x) row[x] = 0;
    }
    return;
  }
  for (int32_t x = 0; x < 2 * width + 2; ++x) zero[x] = 0;
  bvb_hs_prepare_c(i1, i2, width, height, stride, alpha2_q4, coef, flow_scratch);
  bvb_hs_iterate_n_c(coef, zero, 0, uv_out, out_stride, width, height, iterations, flow_scratch,
                     coef_scratch);
}
