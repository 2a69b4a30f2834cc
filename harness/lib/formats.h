// File formats chosen by the file's name, for what bfbench reads and writes: .pgm/.ppm/.pnm
// (Netpbm, io.h), .png (8-bit grey or RGB, through libpng), .flo (Middlebury flow, io.h), .npy
// (NumPy arrays: any buffer with its element type and shape), .csv/.txt (text), .uyvy (raw
// camera frames). A name with another extension is an InputError naming the ones that fit; a
// name with no extension (a device such as /dev/stdout, a FIFO) gets the kind's own format.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "image.h"

namespace bvb {

enum class FileFormat { None, Pnm, Png, Flo, Npy, Text, Uyvy };

// The format a path's extension names (case-insensitive); None when the last path component
// has no '.'. An unknown extension is an InputError listing the known ones.
FileFormat format_of(const std::string &path);

// What a command writes, for the formats it may be written in.
enum class OutputKind { Image, Flow, Text, ImageOrText };
// Throws InputError when `path` names a format `kind` cannot be written in, before anything
// runs: "x.flo: an image is written as .pgm, .ppm, .pnm, .png or .npy".
void check_output_name(const std::string &path, OutputKind kind);

// PNG: 8-bit grey or RGB (palette images are read as RGB, grey of fewer bits widened to 8);
// alpha and 16-bit samples are refused, as is a size beyond kMaxFrameDim (before decoding).
Image parse_png(const std::vector<uint8_t> &bytes, const std::string &name);
std::vector<uint8_t> encode_png(const Image &img, const std::string &name);

// NumPy .npy (format version 1.0, C order): dtype descriptors |u1 |i1 <u2 <i2 <u4 <i4 <f4.
struct NpyArray {
  std::string dtype;
  std::vector<size_t> shape;
  std::vector<uint8_t> data;  // the elements, little-endian, row-major
};
std::vector<uint8_t> encode_npy(const NpyArray &a);
NpyArray parse_npy(const std::vector<uint8_t> &bytes, const std::string &name);
// The dtype descriptor of an integer element of `bytes` bytes (1, 2, 4).
std::string npy_int_dtype(int bytes, bool is_signed);

// Images by name: .pgm (grey), .ppm (RGB), .pnm (either), .png, .npy (uint8, HxW or HxWx3).
// Reading a .pgm that holds colour, or a .ppm that holds grey, is an error: the name says which.
Image read_image(const std::string &path);
// No extension: PNM.
void write_image(const std::string &path, const Image &img);
// Flow by name: .flo, or .npy (float32, H x W x 2: u, v); no extension: .flo.
void write_flow(const std::string &path, const FlowField &flow);
// Text by name: .csv, .txt, or no extension.
void write_text_output(const std::string &path, const std::string &text);

}  // namespace bvb
