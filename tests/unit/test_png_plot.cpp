// tests/support/PngPlot: the PNG file structure against the PNG spec
// (signature, chunk lengths and CRC-32, IHDR fields), the IDAT decoded back
// with zlib's uncompress to the exact scanlines, the stored-block fallback,
// CRC-32 against its published check value, and the log-log plot placing a
// series' marker where the log axes put it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#ifdef TEPHRA_HAVE_ZLIB
#include <zlib.h>
#endif

#include "tests/support/PngPlot.h"

namespace tephra::test {
namespace {

std::uint32_t be32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) | (std::uint32_t(b[at + 2]) << 8) | b[at + 3];
}

struct Chunk {
  std::string type;
  std::vector<std::uint8_t> data;
};

// Splits a PNG into chunks, checking each chunk's CRC-32 over type + data.
std::vector<Chunk> chunks(const std::vector<std::uint8_t>& png) {
  std::vector<Chunk> out;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t n = be32(png, at);
    Chunk c;
    c.type.assign(png.begin() + long(at + 4), png.begin() + long(at + 8));
    c.data.assign(png.begin() + long(at + 8), png.begin() + long(at + 8 + n));
    EXPECT_EQ(be32(png, at + 8 + n), crc32_png(png.data() + at + 4, 4 + n)) << "chunk " << c.type;
    out.push_back(std::move(c));
    at += 12 + n;
  }
  EXPECT_EQ(at, png.size());
  return out;
}

TEST(PngPlot, Crc32CheckValue) {
  // The CRC-32 check value of the ASCII string "123456789" is 0xCBF43926
  // (ISO 3309 / ITU-T V.42 CRC as used by PNG, zlib, gzip).
  const std::string s = "123456789";
  EXPECT_EQ(crc32_png(reinterpret_cast<const std::uint8_t*>(s.data()), s.size()), 0xCBF43926u);
  // IEND's CRC (type only, no data) is AE 42 60 82 in every PNG file.
  const std::uint8_t iend[4] = {'I', 'E', 'N', 'D'};
  EXPECT_EQ(crc32_png(iend, 4), 0xAE426082u);
}

TEST(PngPlot, FileStructureAndPixelsRoundTrip) {
  Image img(37, 21, {10, 20, 30});
  img.set(5, 7, {200, 100, 50});
  img.set(36, 20, {1, 2, 3});
  const auto png = encode_png(img);
  const std::vector<std::uint8_t> sig = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  ASSERT_GE(png.size(), 8u);
  EXPECT_TRUE(std::equal(sig.begin(), sig.end(), png.begin()));
  const auto cs = chunks(png);
  ASSERT_EQ(cs.size(), 3u);
  EXPECT_EQ(cs[0].type, "IHDR");
  EXPECT_EQ(cs[1].type, "IDAT");
  EXPECT_EQ(cs[2].type, "IEND");
  ASSERT_EQ(cs[0].data.size(), 13u);
  EXPECT_EQ(be32(cs[0].data, 0), 37u);  // width
  EXPECT_EQ(be32(cs[0].data, 4), 21u);  // height
  EXPECT_EQ(cs[0].data[8], 8);          // bit depth
  EXPECT_EQ(cs[0].data[9], 2);          // colour type RGB
#ifdef TEPHRA_HAVE_ZLIB
  // Each scanline: filter byte 0 + 3 bytes per pixel.
  const std::size_t row = 1 + 3 * 37;
  std::vector<std::uint8_t> raw(row * 21);
  uLongf n = uLongf(raw.size());
  ASSERT_EQ(uncompress(raw.data(), &n, cs[1].data.data(), uLong(cs[1].data.size())), Z_OK);
  ASSERT_EQ(n, raw.size());
  EXPECT_EQ(raw[7 * row], 0);  // filter type None
  EXPECT_EQ(raw[7 * row + 1 + 3 * 5], 200);
  EXPECT_EQ(raw[7 * row + 1 + 3 * 5 + 1], 100);
  EXPECT_EQ(raw[7 * row + 1 + 3 * 5 + 2], 50);
  EXPECT_EQ(raw[20 * row + 1 + 3 * 36 + 2], 3);
  EXPECT_EQ(raw[0 * row + 1 + 3 * 0], 10);  // background
#else
  GTEST_SKIP() << "zlib not found: IDAT not decoded";
#endif
}

TEST(PngPlot, StoredBlocksInflateToTheInput) {
  // 70000 bytes need two stored blocks (at most 65535 each).
  std::vector<std::uint8_t> raw(70000);
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = std::uint8_t((i * 7) ^ (i >> 8));
  const auto z = zlib_stored(raw);
  EXPECT_EQ(z.size(), 2 + 2 * 5 + raw.size() + 4);  // header, 2 block headers, data, Adler-32
  EXPECT_EQ(z[0], 0x78);
  EXPECT_EQ((z[0] * 256 + z[1]) % 31, 0);  // RFC 1950: CMF*256 + FLG is a multiple of 31
#ifdef TEPHRA_HAVE_ZLIB
  std::vector<std::uint8_t> back(raw.size());
  uLongf n = uLongf(back.size());
  ASSERT_EQ(uncompress(back.data(), &n, z.data(), uLong(z.size())), Z_OK);  // also checks Adler-32
  EXPECT_EQ(back, raw);
#endif
}

TEST(PngPlot, LogLogMarkerAtItsPlace) {
  // One series with points at x = 1, 100 and y = 1e-3, 1e-1: the axes span
  // the decades 1..100 and 1e-3..1e-1 exactly, so the first point's marker is
  // centred on the lower left corner of the plot box (90, height - 70) and
  // the second on the upper right (width - 30, 50) (box of draw_log_log).
  LogLogPlot p;
  p.title = "Test";
  p.xlabel = "x";
  p.ylabel = "y";
  p.series.push_back({"a", {1.0, 100.0}, {1e-3, 1e-1}});
  const Image img = draw_log_log(p);
  const Rgb c = series_colour(0);
  auto is = [&](int x, int y) {
    const Rgb q = img.get(x, y);
    return q.r == c.r && q.g == c.g && q.b == c.b;
  };
  EXPECT_TRUE(is(90 + 2, p.height - 70 - 2));
  // The midpoint of the joining line (log-linear in both axes).
  EXPECT_TRUE(is((90 + p.width - 30) / 2, (p.height - 70 + 50) / 2));
  // Distinct colours for the first eight series.
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < i; ++j) {
      const Rgb a = series_colour(i), b = series_colour(j);
      EXPECT_FALSE(a.r == b.r && a.g == b.g && a.b == b.b);
    }
}

}  // namespace
}  // namespace tephra::test
