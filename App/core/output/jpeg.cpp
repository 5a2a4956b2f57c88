// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/jpeg.hpp"

#include <jerror.h>
#include <jpeglib.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

#include "support/error.hpp"

namespace sliceform {
namespace {

// libjpeg reports errors through a callback that must not return: it jumps back to
// compress(), which then returns false.
struct ErrorJump {
  jpeg_error_mgr manager;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};

void jumpBack(j_common_ptr info) {
  ErrorJump* error = reinterpret_cast<ErrorJump*>(info->err);
  info->err->format_message(info, error->message);
  std::longjmp(error->back, 1);
}

// Compressed bytes go into a vector the caller owns (libjpeg's own jpeg_mem_dest keeps the
// address of its growing buffer to itself until it finishes, so a failure half-way could not
// free it).
struct VectorDestination {
  jpeg_destination_mgr manager;
  std::vector<unsigned char>* out;
  unsigned char buffer[16384];
};

void startDestination(j_compress_ptr info) {
  auto* d = reinterpret_cast<VectorDestination*>(info->dest);
  d->manager.next_output_byte = d->buffer;
  d->manager.free_in_buffer = sizeof d->buffer;
}

// Appends `n` bytes of the buffer; a failure to grow the vector becomes libjpeg's own error
// (an exception must not unwind through libjpeg's C frames).
void append(j_compress_ptr info, size_t n) {
  auto* d = reinterpret_cast<VectorDestination*>(info->dest);
  bool failed = false;
  try {
    d->out->insert(d->out->end(), d->buffer, d->buffer + n);
  } catch (...) {
    failed = true;
  }
  if (failed) ERREXIT(info, JERR_OUT_OF_MEMORY);
}

boolean emptyDestination(j_compress_ptr info) {
  append(info, sizeof reinterpret_cast<VectorDestination*>(info->dest)->buffer);
  startDestination(info);
  return TRUE;
}

void endDestination(j_compress_ptr info) {
  auto* d = reinterpret_cast<VectorDestination*>(info->dest);
  append(info, sizeof d->buffer - d->manager.free_in_buffer);
}

// Everything libjpeg may jump out of, in a function of its own: nothing here is used after
// the jump, and what outlives it (info, the destination, the row) belongs to the caller.
bool compress(jpeg_compress_struct& info, ErrorJump& error, VectorDestination& destination,
              const Picture& picture, int quality, std::vector<unsigned char>& row) {
  if (setjmp(error.back)) return false;
  jpeg_create_compress(&info);
  info.dest = &destination.manager;
  info.image_width = static_cast<JDIMENSION>(picture.width);
  info.image_height = static_cast<JDIMENSION>(picture.height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  for (int c = 0; c < info.num_components; ++c)
    info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    const uint32_t* pixel = picture.pixels.data() + size_t(info.next_scanline) * picture.width;
    for (int x = 0; x < picture.width; ++x) {
      row[3 * x] = (pixel[x] >> 16) & 255;
      row[3 * x + 1] = (pixel[x] >> 8) & 255;
      row[3 * x + 2] = pixel[x] & 255;
    }
    JSAMPROW rows[1] = {row.data()};
    jpeg_write_scanlines(&info, rows, 1);
  }
  jpeg_finish_compress(&info);
  return true;
}

}  // namespace

std::string jpegBytes(const Picture& picture, int quality) {
  if (picture.width <= 0 || picture.height <= 0 ||
      picture.pixels.size() != size_t(picture.width) * size_t(picture.height))
    throw Error(ErrorKind::Io, "cannot encode an empty picture as JPEG");
  std::vector<unsigned char> bytes, row(size_t(picture.width) * 3);
  VectorDestination destination{};
  destination.manager.init_destination = startDestination;
  destination.manager.empty_output_buffer = emptyDestination;
  destination.manager.term_destination = endDestination;
  destination.out = &bytes;
  jpeg_compress_struct info{};
  ErrorJump error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = jumpBack;
  const bool done = compress(info, error, destination, picture, quality, row);
  jpeg_destroy_compress(&info);  // also after a failure: it frees what libjpeg allocated
  if (!done) throw Error(ErrorKind::Io, std::string("cannot encode a picture as JPEG: ") + error.message);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace sliceform
