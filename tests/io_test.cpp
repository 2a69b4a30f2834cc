#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "io.h"

namespace {

std::string tmp_path(const char *name) { return testing::TempDir() + name; }

TEST(Pnm, BinaryGreyRoundTrips) {
  bvb::Image img(5, 3);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = uint8_t(i * 17);
  auto path = tmp_path("rt.pgm");
  bvb::write_pnm(path, img);
  auto back = bvb::read_pnm(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.data, img.data);
}

TEST(Pnm, AsciiWithCommentsAndMaxval) {
  std::string text = "P2\n# comment\n2 1\n# another\n15\n0 15\n";
  auto img = bvb::parse_pnm(std::vector<uint8_t>(text.begin(), text.end()), "t");
  ASSERT_EQ(img.data.size(), 2u);
  EXPECT_EQ(img.data[0], 0);
  EXPECT_EQ(img.data[1], 255);
}

TEST(Pnm, RejectsMalformed) {
  auto bad = [](std::string s) {
    return std::vector<uint8_t>(s.begin(), s.end());
  };
  EXPECT_THROW(bvb::parse_pnm(bad("P7\n1 1\n255\n\0"), "t"), bvb::InputError);
  EXPECT_THROW(bvb::parse_pnm(bad("P5\n4 4\n255\nabc"), "t"), bvb::InputError);  // truncated
  EXPECT_THROW(bvb::parse_pnm(bad("P5\n0 4\n255\n"), "t"), bvb::InputError);
  EXPECT_THROW(bvb::parse_pnm(bad("P5\n99999 4\n255\n"), "t"), bvb::InputError);
  EXPECT_THROW(bvb::parse_pnm(bad("P5\n1 1\n65535\n\x01\x02"), "t"), bvb::InputError);
  EXPECT_THROW(bvb::parse_pnm(bad("P2\n2 1\n255\n1"), "t"), bvb::InputError);
  // A binary value above maxval would be scaled past 255 and wrap; the magic needs whitespace.
  EXPECT_THROW(bvb::parse_pnm(bad("P5\n2 1\n15\n\x05\x10"), "t"), bvb::InputError);
  EXPECT_THROW(bvb::parse_pnm(bad("P6\n1 1\n100\n\x01\x02\xff"), "t"), bvb::InputError);
  EXPECT_THROW(bvb::parse_pnm(bad("P55\n1 1\n255\n\x01"), "t"), bvb::InputError);
  EXPECT_EQ(bvb::parse_pnm(bad("P5\n2 1\n15\n\x05\x0f"), "t").data[1], 255);
}

TEST(Flo, RoundTripsAndRejectsTruncated) {
  bvb::FlowField f(3, 2);
  for (size_t i = 0; i < f.u.size(); ++i) { f.u[i] = float(i) * 0.5f; f.v[i] = -float(i); }
  auto path = tmp_path("rt.flo");
  bvb::write_flo(path, f);
  auto back = bvb::read_flo(path);
  EXPECT_EQ(back.u, f.u);
  EXPECT_EQ(back.v, f.v);
  auto bytes = bvb::read_file(path);
  bytes.pop_back();
  bvb::write_file_atomic(path, bytes);
  EXPECT_THROW(bvb::read_flo(path), bvb::InputError);
}

TEST(Uyvy, SizeMustMatch) {
  auto path = tmp_path("f.uyvy");
  bvb::write_file_atomic(path, std::vector<uint8_t>(4 * 2 * 2, 7));
  EXPECT_EQ(bvb::read_uyvy(path, 4, 2).size(), 16u);
  EXPECT_THROW(bvb::read_uyvy(path, 4, 3), bvb::InputError);
  EXPECT_THROW(bvb::read_uyvy(path, 3, 2), bvb::InputError);
}

}  // namespace

namespace {

// The largest input is bounded before anything is allocated, for files and for streams.
TEST(ReadFile, SizeLimitAndNonFiles) {
  auto path = tmp_path("limit.bin");
  bvb::write_file_atomic(path, std::vector<uint8_t>(100, 1));
  EXPECT_EQ(bvb::read_file(path, 100).size(), 100u);
  try {
    bvb::read_file(path, 99);
    ADD_FAILURE() << "a 100-byte file read with a 99-byte limit";
  } catch (const bvb::InputError &e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  try {
    bvb::read_file("/dev/zero", 1 << 20);
    ADD_FAILURE() << "/dev/zero read to the end";
  } catch (const bvb::InputError &e) {
    EXPECT_NE(std::string(e.what()).find("/dev/zero: more than"), std::string::npos) << e.what();
  }
  try {
    bvb::read_file(testing::TempDir());
    ADD_FAILURE() << "a directory was read";
  } catch (const bvb::InputError &e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

// Atomic writes replace regular files and keep their permissions; a directory is refused.
TEST(WriteFile, RegularFilesKeepTheirModeDirectoriesAreRefused) {
  auto path = tmp_path("mode.bin");
  bvb::write_file_atomic(path, std::vector<uint8_t>(3, 1));
  ASSERT_EQ(chmod(path.c_str(), 0640), 0);
  bvb::write_file_atomic(path, std::vector<uint8_t>(5, 2));
  struct stat st;
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_EQ(st.st_size, 5);
  EXPECT_THROW(bvb::write_file_atomic(testing::TempDir(), std::vector<uint8_t>(1, 0)), bvb::InputError);
}

}  // namespace

#include "check.h"

namespace {

TEST(FirstDifference, CountsInGoodEnglish) {
  bvb::View v;
  std::vector<uint8_t> a(4, 0), b = a;
  b[2] = 1;
  EXPECT_NE(bvb::first_difference(a, b, v).find("1 element differs"), std::string::npos);
  b[3] = 1;
  EXPECT_NE(bvb::first_difference(a, b, v).find("2 elements differ"), std::string::npos);
}

}  // namespace
