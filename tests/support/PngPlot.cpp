#include "tests/support/PngPlot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#ifdef TEPHRA_HAVE_ZLIB
#include <zlib.h>
#endif

namespace tephra::test {

Image::Image(int width, int height, Rgb bg) : w_(width), h_(height), px_(std::size_t(width) * height * 3) {
  for (std::size_t i = 0; i < px_.size(); i += 3) {
    px_[i] = bg.r;
    px_[i + 1] = bg.g;
    px_[i + 2] = bg.b;
  }
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
  const std::size_t i = (std::size_t(y) * w_ + x) * 3;
  px_[i] = c.r;
  px_[i + 1] = c.g;
  px_[i + 2] = c.b;
}

Rgb Image::get(int x, int y) const {
  const std::size_t i = (std::size_t(y) * w_ + x) * 3;
  return {px_[i], px_[i + 1], px_[i + 2]};
}

void Image::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y)
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) set(x, y, c);
}

// DDA: one pixel (or a square of `thickness`) per step along the longer axis.
void Image::line(double x0, double y0, double x1, double y1, Rgb c, int thickness) {
  const int n = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
  const int r = thickness / 2;
  for (int k = 0; k <= n; ++k) {
    const double s = double(k) / n;
    const int x = int(std::lround(x0 + s * (x1 - x0))), y = int(std::lround(y0 + s * (y1 - y0)));
    fill_rect(x - r, y - r, x - r + thickness - 1, y - r + thickness - 1, c);
  }
}

namespace {

// 5x7 glyphs: 7 rows top to bottom, bit 4 = leftmost column.
const std::map<char, std::array<std::uint8_t, 7>>& font() {
  static const std::map<char, std::array<std::uint8_t, 7>> f = {
      {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
      {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
      {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
      {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
      {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
      {'A', {0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}}, {'B', {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E}},
      {'C', {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E}}, {'D', {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C}},
      {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}}, {'F', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10}},
      {'G', {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}}, {'H', {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
      {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}}, {'J', {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C}},
      {'K', {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}}, {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
      {'M', {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}}, {'N', {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11}},
      {'O', {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}}, {'P', {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10}},
      {'Q', {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D}}, {'R', {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11}},
      {'S', {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}}, {'T', {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
      {'U', {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}}, {'V', {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04}},
      {'W', {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A}}, {'X', {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11}},
      {'Y', {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04}}, {'Z', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F}},
      {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}}, {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
      {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}}, {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}},
      {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}}, {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}},
      {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}}, {'^', {0x04, 0x0A, 0x11, 0x00, 0x00, 0x00, 0x00}},
      {',', {0x00, 0x00, 0x00, 0x00, 0x0C, 0x04, 0x08}}, {'=', {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00}},
      {'_', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1F}}, {' ', {0, 0, 0, 0, 0, 0, 0}},
  };
  return f;
}

}  // namespace

void Image::text(int x, int y, const std::string& s, Rgb c, int scale) {
  for (std::size_t k = 0; k < s.size(); ++k) {
    char ch = s[k];
    if (ch >= 'a' && ch <= 'z') ch = char(ch - 'a' + 'A');
    const auto it = font().find(ch);
    if (it == font().end()) continue;  // unknown characters leave a gap
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if (it->second[row] & (0x10 >> col))
          fill_rect(x + (int(k) * 6 + col) * scale, y + row * scale, x + (int(k) * 6 + col) * scale + scale - 1,
                    y + row * scale + scale - 1, c);
  }
}

std::uint32_t crc32_png(const std::uint8_t* data, std::size_t n, std::uint32_t crc) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

void put_chunk(std::vector<std::uint8_t>& out, const char type[4], const std::vector<std::uint8_t>& data) {
  put_u32(out, std::uint32_t(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put_u32(out, crc32_png(out.data() + start, out.size() - start));
}

// Adler-32 (RFC 1950 section 9) of the uncompressed data, the zlib trailer.
std::uint32_t adler32(const std::vector<std::uint8_t>& d) {
  std::uint32_t a = 1, b = 0;
  for (std::uint8_t c : d) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  return (b << 16) | a;
}

}  // namespace

// A zlib stream (RFC 1950) of stored deflate blocks (RFC 1951 section 3.2.4):
// header 78 01; per block of <= 65535 bytes: BFINAL/BTYPE=00 byte, LEN, ~LEN
// (little endian), the bytes; then Adler-32 big endian.
std::vector<std::uint8_t> zlib_stored(const std::vector<std::uint8_t>& raw) {
  std::vector<std::uint8_t> z = {0x78, 0x01};
  std::size_t pos = 0;
  do {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - pos);
    const bool last = pos + n == raw.size();
    z.push_back(last ? 1 : 0);
    z.push_back(std::uint8_t(n & 0xFF));
    z.push_back(std::uint8_t(n >> 8));
    z.push_back(std::uint8_t(~n & 0xFF));
    z.push_back(std::uint8_t((~n >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + long(pos), raw.begin() + long(pos + n));
    pos += n;
  } while (pos < raw.size());
  put_u32(z, adler32(raw));
  return z;
}

namespace {

std::vector<std::uint8_t> zlib_compress(const std::vector<std::uint8_t>& raw) {
#ifdef TEPHRA_HAVE_ZLIB
  uLongf n = compressBound(uLong(raw.size()));
  std::vector<std::uint8_t> z(n);
  if (compress2(z.data(), &n, raw.data(), uLong(raw.size()), 9) != Z_OK)
    throw std::runtime_error("encode_png: zlib compress2 failed");
  z.resize(n);
  return z;
#else
  return zlib_stored(raw);
#endif
}

}  // namespace

bool png_uses_zlib() {
#ifdef TEPHRA_HAVE_ZLIB
  return true;
#else
  return false;
#endif
}

std::vector<std::uint8_t> encode_png(const Image& img) {
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  std::vector<std::uint8_t> ihdr;
  put_u32(ihdr, std::uint32_t(img.width()));
  put_u32(ihdr, std::uint32_t(img.height()));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // depth 8, RGB, deflate, filter 0, no interlace
  put_chunk(out, "IHDR", ihdr);
  std::vector<std::uint8_t> raw;
  raw.reserve(std::size_t(img.height()) * (1 + 3 * img.width()));
  for (int y = 0; y < img.height(); ++y) {
    raw.push_back(0);  // filter type None
    const auto row = img.rgb().begin() + long(y) * 3 * img.width();
    raw.insert(raw.end(), row, row + 3 * img.width());
  }
  put_chunk(out, "IDAT", zlib_compress(raw));
  put_chunk(out, "IEND", {});
  return out;
}

void write_png(const Image& img, const std::string& path) {
  const auto bytes = encode_png(img);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("write_png: cannot open " + path);
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !ok) throw std::runtime_error("write_png: cannot write " + path);
}

Rgb series_colour(int i) {
  static const Rgb c[8] = {{0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {204, 121, 167},
                           {230, 159, 0}, {86, 180, 233}, {0, 0, 0}, {240, 228, 66}};
  return c[((i % 8) + 8) % 8];
}

Image draw_log_log(const LogLogPlot& plot) {
  const Rgb black{0, 0, 0}, grey{220, 220, 220};
  Image img(plot.width, plot.height);
  // Data range in decades (whole decades around the data).
  double lx0 = 1e300, lx1 = -1e300, ly0 = 1e300, ly1 = -1e300;
  for (const auto& s : plot.series)
    for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
      if (!(s.x[k] > 0.0 && s.y[k] > 0.0)) continue;
      lx0 = std::min(lx0, std::log10(s.x[k]));
      lx1 = std::max(lx1, std::log10(s.x[k]));
      ly0 = std::min(ly0, std::log10(s.y[k]));
      ly1 = std::max(ly1, std::log10(s.y[k]));
    }
  if (lx0 > lx1) lx0 = 0, lx1 = 1, ly0 = 0, ly1 = 1;
  const int dx0 = int(std::floor(lx0)), dx1 = std::max(dx0 + 1, int(std::ceil(lx1)));
  const int dy0 = int(std::floor(ly0)), dy1 = std::max(dy0 + 1, int(std::ceil(ly1)));
  // Plot box in pixels.
  const int left = 90, right = plot.width - 30, top = 50, bottom = plot.height - 70;
  auto px = [&](double x) { return left + (std::log10(x) - dx0) / (dx1 - dx0) * (right - left); };
  auto py = [&](double y) { return bottom - (std::log10(y) - dy0) / (dy1 - dy0) * (bottom - top); };
  // Grid and ticks: decades labelled 1E+k, minor ticks at 2..9 x 10^k.
  for (int d = dx0; d <= dx1; ++d) {
    const double x = px(std::pow(10.0, d));
    img.line(x, top, x, bottom, grey);
    img.line(x, bottom, x, bottom + 8, black);
    char buf[16];
    std::snprintf(buf, sizeof buf, "1E%+d", d);
    img.text(int(x) - Image::text_width(buf) / 2, bottom + 14, buf, black);
    for (int m = 2; m <= 9 && d < dx1; ++m) {
      const double xm = px(m * std::pow(10.0, d));
      img.line(xm, bottom, xm, bottom + 4, black);
    }
  }
  for (int d = dy0; d <= dy1; ++d) {
    const double y = py(std::pow(10.0, d));
    img.line(left, y, right, y, grey);
    img.line(left - 8, y, left, y, black);
    char buf[16];
    std::snprintf(buf, sizeof buf, "1E%+d", d);
    img.text(left - 12 - Image::text_width(buf), int(y) - 3, buf, black);
    for (int m = 2; m <= 9 && d < dy1; ++m) {
      const double ym = py(m * std::pow(10.0, d));
      img.line(left - 4, ym, left, ym, black);
    }
  }
  // Axes box, title and labels.
  img.line(left, top, right, top, black);
  img.line(left, bottom, right, bottom, black);
  img.line(left, top, left, bottom, black);
  img.line(right, top, right, bottom, black);
  img.text((plot.width - Image::text_width(plot.title, 2)) / 2, 15, plot.title, black, 2);
  img.text((left + right - Image::text_width(plot.xlabel)) / 2, bottom + 36, plot.xlabel, black);
  // The y label runs horizontally above the axis (the font has no rotation).
  img.text(10, top - 16, plot.ylabel, black);
  // Series: lines and square markers.
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const auto& s = plot.series[i];
    const Rgb c = series_colour(int(i));
    for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
      if (!(s.x[k] > 0.0 && s.y[k] > 0.0)) continue;
      const int x = int(std::lround(px(s.x[k]))), y = int(std::lround(py(s.y[k])));
      img.fill_rect(x - 3, y - 3, x + 3, y + 3, c);
      if (k > 0 && s.x[k - 1] > 0.0 && s.y[k - 1] > 0.0) img.line(px(s.x[k - 1]), py(s.y[k - 1]), x, y, c, 2);
    }
  }
  // Legend, upper right inside the box.
  std::size_t widest = 0;
  for (const auto& s : plot.series) widest = std::max(widest, s.label.size());
  const int lw = 40 + Image::text_width(std::string(widest, 'M')), lx = right - lw - 10, ly = top + 10;
  img.fill_rect(lx, ly, lx + lw, ly + 8 + 16 * int(plot.series.size()), {255, 255, 255});
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const int y = ly + 10 + 16 * int(i);
    img.line(lx + 6, y, lx + 28, y, series_colour(int(i)), 2);
    img.fill_rect(lx + 14, y - 3, lx + 20, y + 3, series_colour(int(i)));
    img.text(lx + 34, y - 3, plot.series[i].label, black);
  }
  const int lb = ly + 8 + 16 * int(plot.series.size());
  img.line(lx, ly, lx + lw, ly, black);
  img.line(lx, lb, lx + lw, lb, black);
  img.line(lx, ly, lx, lb, black);
  img.line(lx + lw, ly, lx + lw, lb, black);
  return img;
}

}  // namespace tephra::test
