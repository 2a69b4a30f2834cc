// Check, bench and run for bvb/yuv.h (UYVY 4:2:2 to grey and to RGB24).
#include "bvb/yuv.h"

#include <sys/stat.h>

#include "family.h"
#include "io.h"
#include "patterns.h"
#include "scene/render.h"
#include "names.h"

namespace bvb {
namespace {

// A UYVY frame of w x h pixels in rows of `stride` bytes. Real: a crop of a real colour frame
// through the scene generator's RGB -> UYVY, so U and V carry real chroma; the other patterns
// fill all bytes (U, Y and V alike), which reaches every corner of the conversion's clamps.
std::vector<uint8_t> uyvy_plane(Pattern p, int w, int h, int stride, Rng &rng, const std::string &frames_real) {
  if (p == Pattern::Real && !frames_real.empty()) {
    static const char *frames[] = {"RubberWhale/frame10.ppm", "Dimetrodon/frame10.ppm",
                                   "RubberWhale/frame11.ppm", "Dimetrodon/frame11.ppm"};
    const std::string path = frames_real + "/" + frames[rng.uniform(0, 3)];
    struct stat st;
    if (stat(path.c_str(), &st) == 0) {
      const Image src = read_pnm(path);
      Image crop(w, h, 3);
      const int x0 = src.width > w ? rng.uniform(0, src.width - w) : 0;
      const int y0 = src.height > h ? rng.uniform(0, src.height - h) : 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          for (int c = 0; c < 3; ++c)
            crop.at(x, y, c) = src.at((x0 + x) % src.width, (y0 + y) % src.height, c);
      const std::vector<uint8_t> packed = rgb_to_uyvy(crop);
      std::vector<uint8_t> d(size_t(stride) * (h - 1) + 2 * w);
      for (auto &v : d) v = uint8_t(rng.u32());
      for (int y = 0; y < h; ++y)
        std::copy(packed.begin() + size_t(y) * 2 * w, packed.begin() + size_t(y + 1) * 2 * w,
                  d.begin() + size_t(y) * stride);
      return d;
    }
  }
  return make_plane(p, 2 * w, h, stride, rng, frames_real);
}

CheckCall yuv_call(const std::string &kernel, int w, int h, int sstride, int dstride, std::vector<uint8_t> src,
                   const std::string &case_name) {
  CheckCall c;
  c.kernel = kernel;
  c.case_name = case_name;
  c.pixels = double(w) * h;
  const bool rgb = kernel == "uyvy_to_rgb24";
  const int out_row = rgb ? 3 * w : w;
  const View sv{1, false, 2 * w, h, sstride}, dv{1, false, out_row, h, dstride, rgb ? 3 : 1};
  int is = c.in("src", std::move(src), sv);
  int id = c.out("dst", size_t(dstride) * (h - 1) + out_row, dv);
  c.buf(is).buf(id).word(w).word(h).word(sstride).word(dstride);
  if (rgb) {
    c.host = [=](HostBuffers &m) { bvb_uyvy_to_rgb24_c(m.u8(is), m.u8(id), w, h, sstride, dstride); };
  } else {
    int iscr = c.scratch("scratch", BVB_UYVY_TO_GREY_SCRATCH_BYTES(w));
    c.buf(iscr);
    c.host = [=](HostBuffers &m) { bvb_uyvy_to_grey_c(m.u8(is), m.u8(id), w, h, sstride, dstride, m.u8(iscr)); };
  }
  return c;
}

void check(Checker &ck) {
  for (const char *kernel : {"uyvy_to_grey", "uyvy_to_rgb24"}) {
    Rng &rng = ck.rng();
    const bool rgb = std::string(kernel) == "uyvy_to_rgb24";
    std::vector<Size> sizes = check_sizes(2, 1, rng, ck.options().campaign);
    // Widths 2..9 meet every combination of head, groups and tail in the assembly.
    for (int w = 2; w <= 10; w += 2) sizes.push_back({w, 3});
    for (Size s : sizes) {
      const int w = s.w + (s.w & 1);  // UYVY widths are even
      for (Pattern p : ck.patterns()) {
        // Any stride, odd ones included: rows of every alignment on both sides.
        const int ss = pick_stride(2 * w, rng), ds = pick_stride(rgb ? 3 * w : w, rng);
        std::string name = size_name(w, s.h) + " strides " + std::to_string(ss) +
                           "/" + std::to_string(ds) + " " + pattern_name(p);
        CheckCall c = yuv_call(kernel, w, s.h, ss, ds, uyvy_plane(p, w, s.h, ss, rng, ck.options().frames_real),
                               name);
        for (auto &b : c.bufs)
          if (b.role != Role::Scratch) b.skew = uint32_t(rng.uniform(0, 3));
        // Grey: half the calls where the robot runs it (row bands by DMA, firmware/asm/yuv.S).
        if (rgb)
          ck.place_randomly(c);
        else
          ck.place_streaming(c, 2, rng);
        ck.add(std::move(c));
      }
    }
  }
}

CheckCall bench_call(const std::string &kernel, int w, int h, Rng &rng) {
  const bool rgb = kernel == "uyvy_to_rgb24";
  CheckCall c = yuv_call(kernel, w, h, 2 * w, rgb ? 3 * w : w, uyvy_plane(Pattern::Noise, w, h, 2 * w, rng, ""),
                         size_name(w, h));
  // Frames in SDRAM, the grey kernel's band buffers in L1 bank B.
  if (!rgb) c.bufs[2].place = BVB_PLACE_L1B;
  return c;
}

// Grey: the larger of the compute (three ops per four pixels, 0.75 cycles, firmware/asm/yuv.S)
// and the bus (2 bytes in, 1 out per pixel at 0.5 byte per core cycle, bvb/dma.h: 6 cycles).
// RGB has no assembly.
double lower_bound(const std::string &kernel, int w, int h) {
  return kernel == "uyvy_to_grey" ? 6.0 * w * h : 0;
}

RunPlan plan_run(RunRequest &req) {
  if (req.inputs.size() != 1) throw InputError(req.kernel + " takes one --in frame");
  const std::string &path = req.inputs[0];
  const bool raw = format_of(path) == FileFormat::Uyvy;
  int w, h;
  std::vector<uint8_t> bytes;
  if (raw) {
    if (req.raw_width <= 0 || req.raw_height <= 0) throw InputError(path + ": raw UYVY input needs --size WxH");
    w = req.raw_width;
    h = req.raw_height;
    bytes = read_uyvy(path, w, h);
  } else {
    // A colour frame goes through the scene generator's RGB -> UYVY (a grey one as grey RGB).
    Image img = read_image(path);
    if (img.width % 2) throw InputError(path + ": UYVY needs an even width");
    if (img.channels == 1) {
      Image c(img.width, img.height, 3);
      for (size_t i = 0; i < img.data.size(); ++i) c.data[3 * i] = c.data[3 * i + 1] = c.data[3 * i + 2] = img.data[i];
      img = c;
    }
    w = img.width;
    h = img.height;
    bytes = rgb_to_uyvy(img);
  }
  req.params.check_all_used();
  const bool rgb = req.kernel == "uyvy_to_rgb24";
  RunPlan p;
  p.call = yuv_call(req.kernel, w, h, 2 * w, rgb ? 3 * w : w, bytes, "run");
  p.write = [w, h, rgb](std::vector<std::vector<uint8_t>> &bufs, const std::string &out) {
    Image img(w, h, rgb ? 3 : 1);
    img.data = bufs[1];
    write_image(out, img);
  };
  p.summary = size_name(w, h);
  return p;
}

const Family kYuv{"yuv", {"uyvy_to_grey", "uyvy_to_rgb24"}, check, bench_call, lower_bound, plan_run};
BVB_FAMILY(kYuv);

}  // namespace
}  // namespace bvb
