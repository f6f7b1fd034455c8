#include "src/image_io.h"

#include <array>

#include <png.h>
#include <zlib.h>

#include "src/errors.h"
#include "src/plugin.h"

namespace sandpic {

namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  auto* out = static_cast<std::vector<uchar>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + n);
}
void flush(png_structp) {}

// No C++ object lives in this frame: libpng leaves it by longjmp on error.
bool write_png(png_structp png, png_infop info, const cv::Mat* img, png_bytepp rows, std::vector<uchar>* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append, flush);
  // OpenCV 4.6's PngEncoder without parameters: "tune parameters for speed".
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_compression_strategy(png, Z_RLE);
  const int cn = img->channels();
  png_set_IHDR(png, info, png_uint_32(img->cols), png_uint_32(img->rows), 8,
               cn == 1 ? PNG_COLOR_TYPE_GRAY : cn == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_set_bgr(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

// A palette PNG: up to 256 colours, packed 1, 2, 4 or 8 bits a pixel,
// unfiltered (the PNG spec's advice for palette pictures). Same longjmp rule.
bool write_indexed(png_structp png, png_infop info, int w, int h, int depth, const png_color* palette, int colours,
                   png_bytepp rows, std::vector<uchar>* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append, flush);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_compression_strategy(png, Z_RLE);
  png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), depth, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_PLTE(png, info, palette, colours);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

// libpng's write structs around `write` (one of the above), freed however it
// ends; its bytes, or SimulationError.
template <class Write>
std::vector<uchar> with_png_writer(Write write) {
  std::vector<uchar> out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && write(png, info, &out);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw SimulationError("PNG encoding failed (libpng)");
  return out;
}

struct Plugin {
  bool (*read)(const char*, int, cv::Mat*) = nullptr;
  bool (*decode)(const void*, size_t, int, cv::Mat*) = nullptr;
  bool (*encode)(const char*, const cv::Mat*, int, std::vector<uchar>*) = nullptr;
};

const Plugin& plugin() {
  static const Plugin p = [] {
    const auto f = load_plugin("libsandpic_image.so", SANDPIC_IMAGE_PLUGIN, "the picture decoder",
                               {"sandpic_image_read", "sandpic_image_decode", "sandpic_image_encode"});
    Plugin q;
    q.read = reinterpret_cast<decltype(q.read)>(f[0]);
    q.decode = reinterpret_cast<decltype(q.decode)>(f[1]);
    q.encode = reinterpret_cast<decltype(q.encode)>(f[2]);
    return q;
  }();
  return p;
}

}  // namespace

std::vector<uchar> encode_png(const cv::Mat& img) {
  const int cn = img.channels();
  if (img.empty() || img.depth() != CV_8U || (cn != 1 && cn != 3 && cn != 4))
    throw SimulationError("PNG encoding failed: " + std::to_string(img.cols) + " x " + std::to_string(img.rows) +
                          " picture of type " + std::to_string(img.type()) + " is not 8-bit grey, BGR or BGRA");
  std::vector<png_bytep> rows(size_t(img.rows));
  for (int y = 0; y < img.rows; ++y) rows[size_t(y)] = const_cast<png_bytep>(img.ptr<uchar>(y));
  return with_png_writer([&](png_structp png, png_infop info, std::vector<uchar>* out) {
    return write_png(png, info, &img, rows.data(), out);
  });
}

std::vector<uchar> encode_png_indexed(const cv::Mat& img) {
  if (img.empty() || img.type() != CV_8UC3) return encode_png(img);
  // The palette in order of first appearance (row by row): the same picture,
  // the same bytes. A run of one colour costs one compare.
  std::vector<png_color> palette;
  cv::Mat index(img.rows, img.cols, CV_8U);
  uint32_t last = 0xffffffff;
  uchar last_i = 0;
  std::array<int16_t, 4096> hashed;  // a colour's 12-bit hash -> its index (-1: none)
  hashed.fill(-1);
  for (int y = 0; y < img.rows; ++y) {
    const uchar* p = img.ptr<uchar>(y);
    uchar* q = index.ptr<uchar>(y);
    for (int x = 0; x < img.cols; ++x, p += 3) {
      const uint32_t c = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16;
      if (c != last) {
        uint32_t h = (c * 2654435761u) >> 20;
        for (;; h = (h + 1) & 4095) {
          const int16_t i = hashed[h];
          if (i < 0) {
            if (palette.size() == 256) return encode_png(img);  // too many colours for a palette
            hashed[h] = int16_t(palette.size());
            palette.push_back({p[2], p[1], p[0]});
            last_i = uchar(palette.size() - 1);
            break;
          }
          const png_color& e = palette[size_t(i)];
          if (e.red == p[2] && e.green == p[1] && e.blue == p[0]) {
            last_i = uchar(i);
            break;
          }
        }
        last = c;
      }
      q[x] = last_i;
    }
  }
  const int n = int(palette.size()), depth = n <= 2 ? 1 : n <= 4 ? 2 : n <= 16 ? 4 : 8;
  // Rows packed at `depth` bits, the leftmost pixel in the high bits.
  const int per_byte = 8 / depth, row_bytes = (img.cols + per_byte - 1) / per_byte;
  cv::Mat packed = depth == 8 ? index : cv::Mat(img.rows, row_bytes, CV_8U, cv::Scalar(0));
  if (depth < 8)
    for (int y = 0; y < img.rows; ++y) {
      const uchar* q = index.ptr<uchar>(y);
      uchar* r = packed.ptr<uchar>(y);
      for (int x = 0; x < img.cols; ++x) r[x / per_byte] |= uchar(q[x] << (8 - depth * (x % per_byte + 1)));
    }
  std::vector<png_bytep> rows(size_t(img.rows));
  for (int y = 0; y < img.rows; ++y) rows[size_t(y)] = packed.ptr<uchar>(y);
  return with_png_writer([&](png_structp png, png_infop info, std::vector<uchar>* out) {
    return write_indexed(png, info, img.cols, img.rows, depth, palette.data(), n, rows.data(), out);
  });
}

cv::Mat read_picture(const std::string& path, ImageRead how) {
  cv::Mat out;
  plugin().read(path.c_str(), int(how), &out);
  return out;
}

cv::Mat decode_picture(const void* data, size_t size, ImageRead how) {
  cv::Mat out;
  plugin().decode(data, size, int(how), &out);
  return out;
}

std::vector<uchar> encode_jpeg(const cv::Mat& bgr, int quality) {
  std::vector<uchar> out;
  if (!plugin().encode(".jpg", &bgr, quality, &out)) throw SimulationError("JPEG encoding failed");
  return out;
}

std::vector<uchar> encode_picture(const std::string& ext, const cv::Mat& img) {
  std::vector<uchar> out;
  if (!plugin().encode(ext.c_str(), &img, -1, &out)) throw SimulationError("cannot encode a picture as " + ext);
  return out;
}

}  // namespace sandpic
