#pragma once
// A small PNG writer (8-bit RGB, one IDAT, zlib-compressed when zlib is
// found, else stored deflate blocks) and a log-log line plot with axes,
// decade ticks, labelled series in distinct colours and a legend, drawn with
// a built-in 5x7 bitmap font. For benchmark figures (tests/bench/).
//
// PNG layout (ISO/IEC 15948 / W3C PNG spec, sections 5 and 11):
//   signature 89 50 4E 47 0D 0A 1A 0A, then chunks
//   [length u32 BE][type 4][data][CRC-32 over type+data, u32 BE]:
//   IHDR (width, height, bit depth 8, colour type 2 = RGB, 0, 0, 0),
//   IDAT (zlib stream of the scanlines, each preceded by filter byte 0), IEND.
#include <cstdint>
#include <string>
#include <vector>

namespace tephra::test {

struct Rgb {
  std::uint8_t r = 255, g = 255, b = 255;
};

class Image {
 public:
  Image(int width, int height, Rgb background = {});
  int width() const { return w_; }
  int height() const { return h_; }
  void set(int x, int y, Rgb c);  // ignores pixels outside the image
  Rgb get(int x, int y) const;
  void line(double x0, double y0, double x1, double y1, Rgb c, int thickness = 1);
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);  // inclusive corners
  // Text in the built-in 5x7 font (digits, letters, . - + : / ( ) ^ , = _ space;
  // lower case drawn as upper case), top-left at (x, y), `scale` pixels per dot.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 1);
  static int text_width(const std::string& s, int scale = 1) { return int(s.size()) * 6 * scale; }
  const std::vector<std::uint8_t>& rgb() const { return px_; }

 private:
  int w_, h_;
  std::vector<std::uint8_t> px_;  // row-major RGB
};

// CRC-32 (ISO 3309, polynomial 0xEDB88320 reflected), as PNG chunks use.
std::uint32_t crc32_png(const std::uint8_t* data, std::size_t n, std::uint32_t crc = 0);
// The PNG file bytes of an image.
std::vector<std::uint8_t> encode_png(const Image& img);
// Writes the PNG; throws std::runtime_error when the file cannot be written.
void write_png(const Image& img, const std::string& path);
// A zlib stream of stored (uncompressed) deflate blocks: encode_png's IDAT
// without zlib.
std::vector<std::uint8_t> zlib_stored(const std::vector<std::uint8_t>& raw);
// true when encode_png compresses with zlib (else stored blocks).
bool png_uses_zlib();

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  // > 0 (log axes); points joined in the given order
};

struct LogLogPlot {
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
  int width = 800, height = 600;
};

// Draws the plot: axes over whole decades around the data, ticks and labels
// 10^k at decades, a marker per point, a legend in the upper right.
Image draw_log_log(const LogLogPlot& plot);
// The colour of series i (distinct for i < 8).
Rgb series_colour(int i);

}  // namespace tephra::test
