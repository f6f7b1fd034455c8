#pragma once
// Pictures in and out. Every run writes a PNG, so PNG is encoded here with
// libpng, with the settings OpenCV's imencode uses (the same bytes); reading
// pictures (any format) and the studio's JPEG frames go through OpenCV's
// imgcodecs, loaded on first use from a plugin (libsandpic_image.so,
// src/image_plugin.cpp, built beside the executable): Debian builds imgcodecs
// with GDAL, whose ~120 shared libraries cost every process about 50 ms at
// start, and most runs read no picture.
#include <cstddef>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace sandpic {

// An 8-bit picture of 1, 3 (BGR) or 4 (BGRA) channels as PNG bytes, as
// cv::imencode(".png", img) makes them. Throws SimulationError otherwise.
std::vector<uchar> encode_png(const cv::Mat& img);

// The same picture as a palette PNG when it has at most 256 colours (a sand
// picture without a background image or figures has 4-6), else as
// encode_png. Smaller and faster to decode: the studio's previews.
std::vector<uchar> encode_png_indexed(const cv::Mat& img);

// How a decoded picture comes out: 8-bit BGR (16-bit, grey and alpha
// converted, as cv::IMREAD_COLOR), 8-bit grey (cv::IMREAD_GRAYSCALE) or as
// stored (cv::IMREAD_UNCHANGED).
enum class ImageRead { Color, Grey, Unchanged };

// A picture file or bytes through imgcodecs; an empty Mat if it is not one
// (the codec's own complaints on stderr are left to the caller to hide).
// Throws InputError (exit 2) when the plugin cannot be loaded.
cv::Mat read_picture(const std::string& path, ImageRead how = ImageRead::Color);
cv::Mat decode_picture(const void* data, size_t size, ImageRead how = ImageRead::Color);

// JPEG bytes of an 8-bit BGR picture at `quality` (0-100), and any picture
// OpenCV can write (16-bit PNG too) by its extension (".png"), through
// imgcodecs. Throw SimulationError when OpenCV cannot.
std::vector<uchar> encode_jpeg(const cv::Mat& bgr, int quality);
std::vector<uchar> encode_picture(const std::string& ext, const cv::Mat& img);

}  // namespace sandpic
