// File formats by name (harness/lib/formats.h): PNG through libpng, NumPy .npy, the extension
// rules, and what a name may hold.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "family.h"
#include "formats.h"
#include "io.h"

namespace {

using namespace bvb;

std::string tmp_path(const char *name) { return testing::TempDir() + name; }

Image pattern(int w, int h, int c) {
  Image img(w, h, c);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = uint8_t(i * 37 + 11);
  return img;
}

TEST(Formats, ExtensionsNameFormats) {
  EXPECT_EQ(format_of("a/b.pgm"), FileFormat::Pnm);
  EXPECT_EQ(format_of("b.PPM"), FileFormat::Pnm);
  EXPECT_EQ(format_of("b.pnm"), FileFormat::Pnm);
  EXPECT_EQ(format_of("b.png"), FileFormat::Png);
  EXPECT_EQ(format_of("b.flo"), FileFormat::Flo);
  EXPECT_EQ(format_of("b.npy"), FileFormat::Npy);
  EXPECT_EQ(format_of("b.csv"), FileFormat::Text);
  EXPECT_EQ(format_of("b.uyvy"), FileFormat::Uyvy);
  EXPECT_EQ(format_of("/dev/null"), FileFormat::None);
  EXPECT_EQ(format_of("dir.d/out"), FileFormat::None);  // the dot is in a directory's name
  try {
    format_of("out.jpg");
    ADD_FAILURE() << ".jpg accepted";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("out.jpg: unknown extension '.jpg'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_output_name("x.flo", OutputKind::Image), InputError);
  EXPECT_THROW(check_output_name("x.png", OutputKind::Flow), InputError);
  EXPECT_THROW(check_output_name("x.pgm", OutputKind::Text), InputError);
  EXPECT_NO_THROW(check_output_name("x.npy", OutputKind::Text));
  EXPECT_NO_THROW(check_output_name("x.txt", OutputKind::ImageOrText));
}

// 8-bit grey and RGB round-trip through real PNG bytes (the signature, then libpng decoding).
TEST(Formats, PngGreyAndRgbRoundTrip) {
  for (int c : {1, 3}) {
    const Image img = pattern(13, 7, c);
    const std::string path = tmp_path(c == 1 ? "rt_grey.png" : "rt_rgb.png");
    write_image(path, img);
    const std::vector<uint8_t> bytes = read_file(path);
    ASSERT_GE(bytes.size(), 8u);
    EXPECT_EQ(std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8), 0) << "not PNG bytes";
    const Image back = read_image(path);
    EXPECT_EQ(back.width, 13);
    EXPECT_EQ(back.height, 7);
    EXPECT_EQ(back.channels, c);
    EXPECT_EQ(back.data, img.data);
  }
}

TEST(Formats, PngMalformedAndUnsupported) {
  std::vector<uint8_t> png = encode_png(pattern(8, 8, 1), "t");
  EXPECT_THROW(parse_png(std::vector<uint8_t>(png.begin(), png.begin() + 20), "t"), InputError);
  std::vector<uint8_t> text = {'P', '5', '\n'};
  EXPECT_THROW(parse_png(text, "t"), InputError);
  // A corrupted image body (past the header) is reported, not decoded into garbage silently.
  std::vector<uint8_t> broken = png;
  for (size_t i = 40; i < broken.size() - 12; ++i) broken[i] ^= 0x5a;
  EXPECT_THROW(parse_png(broken, "t"), InputError);
}

// The .npy header as NumPy 1.0 writes it: magic, version, length, a dict padded to 64 bytes.
TEST(Formats, NpyHeaderAndRoundTrip) {
  NpyArray a{"<i2", {2, 3}, std::vector<uint8_t>(12)};
  for (size_t i = 0; i < a.data.size(); ++i) a.data[i] = uint8_t(i);
  const std::vector<uint8_t> b = encode_npy(a);
  // 10 bytes of prefix and a 60-character dict: padded to 128 bytes, then the 12 data bytes.
  ASSERT_EQ(b.size(), 128u + 12u);
  EXPECT_EQ(std::memcmp(b.data(), "\x93NUMPY\x01\x00", 8), 0);
  EXPECT_EQ(b[8] | b[9] << 8, 118);
  const std::string header(b.begin() + 10, b.begin() + 128);
  EXPECT_EQ(header.rfind("{'descr': '<i2', 'fortran_order': False, 'shape': (2, 3), }", 0), 0u) << header;
  EXPECT_EQ(header.back(), '\n');
  const NpyArray back = parse_npy(b, "t");
  EXPECT_EQ(back.dtype, "<i2");
  EXPECT_EQ(back.shape, (std::vector<size_t>{2, 3}));
  EXPECT_EQ(back.data, a.data);
  // One dimension is written (n,), as Python spells a 1-tuple.
  const std::vector<uint8_t> flat = encode_npy({"|u1", {5}, std::vector<uint8_t>(5)});
  EXPECT_NE(std::string(flat.begin(), flat.end()).find("'shape': (5,)"), std::string::npos);
  std::vector<uint8_t> short_data = b;
  short_data.pop_back();
  EXPECT_THROW(parse_npy(short_data, "t"), InputError);
  EXPECT_THROW(parse_npy(std::vector<uint8_t>(b.begin(), b.begin() + 9), "t"), InputError);
}

TEST(Formats, ImagesByNameAndWhatTheNameSays) {
  const Image grey = pattern(6, 4, 1), rgb = pattern(6, 4, 3);
  write_image(tmp_path("n.npy"), rgb);
  const Image back = read_image(tmp_path("n.npy"));
  EXPECT_EQ(back.channels, 3);
  EXPECT_EQ(back.data, rgb.data);
  EXPECT_THROW(write_image(tmp_path("c.pgm"), rgb), InputError);  // a .pgm is grey
  EXPECT_THROW(write_image(tmp_path("g.ppm"), grey), InputError);  // a .ppm is colour
  write_image(tmp_path("c.pnm"), rgb);
  EXPECT_EQ(read_image(tmp_path("c.pnm")).channels, 3);
  write_pnm(tmp_path("colour_named_grey.pgm"), rgb);  // P6 bytes under a grey name
  EXPECT_THROW(read_image(tmp_path("colour_named_grey.pgm")), InputError);
  EXPECT_THROW(write_image(tmp_path("x.flo"), grey), InputError);
  EXPECT_THROW(read_image(tmp_path("x.csv")), InputError);
}

TEST(Formats, FlowAsNpyIsFloat32HxWx2) {
  FlowField f(3, 2);
  for (size_t i = 0; i < f.u.size(); ++i) f.u[i] = 0.5f * float(i), f.v[i] = -float(i);
  write_flow(tmp_path("f.npy"), f);
  const NpyArray a = parse_npy(read_file(tmp_path("f.npy")), "f.npy");
  EXPECT_EQ(a.dtype, "<f4");
  EXPECT_EQ(a.shape, (std::vector<size_t>{2, 3, 2}));
  float u5, v5;
  std::memcpy(&u5, &a.data[5 * 8], 4);
  std::memcpy(&v5, &a.data[5 * 8 + 4], 4);
  EXPECT_EQ(u5, 2.5f);
  EXPECT_EQ(v5, -5.f);
  EXPECT_THROW(write_flow(tmp_path("f.png"), f), InputError);
}

// A buffer's view gives the array its shape: the stride's padding is left out, interleaved
// channels become a last axis.
TEST(Formats, BufferAsNpyFollowsItsView) {
  Buffer b;
  b.name = "uv";
  b.view = View{2, true, 4, 2, 6, 2};  // 2 rows of 2 (u, v) pairs, rows 6 elements apart
  std::vector<uint8_t> data(2 * (6 + 4));
  for (size_t i = 0; i < data.size() / 2; ++i) data[2 * i] = uint8_t(i), data[2 * i + 1] = 0xff;
  const NpyArray a = npy_of_buffer(b, data);
  EXPECT_EQ(a.dtype, "<i2");
  EXPECT_EQ(a.shape, (std::vector<size_t>{2, 2, 2}));
  ASSERT_EQ(a.data.size(), 16u);
  EXPECT_EQ(a.data[0], 0);
  EXPECT_EQ(a.data[8], 6);  // the second row starts at element 6, not 4
  Buffer flat;
  flat.view = View{4, false};
  EXPECT_EQ(npy_of_buffer(flat, std::vector<uint8_t>(12)).shape, (std::vector<size_t>{3}));
  EXPECT_EQ(npy_of_buffer(flat, std::vector<uint8_t>(12)).dtype, "<u4");
}

}  // namespace
