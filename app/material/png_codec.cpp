#include "app/material/png_codec.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace skinlayer {
namespace {

// libpng reports errors by longjmp to the setjmp of the function that called it. The functions holding a setjmp
// below keep only trivially destructible locals, and copy libpng's message into this fixed buffer first.
struct PngErrorMessage {
  char text[256] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngErrorMessage*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // warnings (an unknown chunk, ...) are not failures

struct MemoryWriter {
  std::string* bytes;
};

void write_to_memory(png_structp png, png_bytep data, png_size_t length) {
  auto* writer = static_cast<MemoryWriter*>(png_get_io_ptr(png));
  writer->bytes->append(reinterpret_cast<const char*>(data), length);
}

void flush_memory(png_structp) {}

struct MemoryReader {
  const unsigned char* data;
  std::size_t size;
  std::size_t offset;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t length) {
  auto* reader = static_cast<MemoryReader*>(png_get_io_ptr(png));
  if (length > reader->size - reader->offset) png_error(png, "the file ends early (truncated)");
  std::memcpy(out, reader->data + reader->offset, length);
  reader->offset += length;
}

// Returns false with error->text set when libpng fails.
bool encode(int width, int height, png_bytepp rows, png_textp texts, int text_count, std::string* bytes,
            PngErrorMessage* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_error, on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  MemoryWriter writer{bytes};
  png_set_write_fn(png, &writer, write_to_memory, flush_memory);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (text_count > 0) png_set_text(png, info, texts, text_count);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

constexpr png_alloc_size_t kMaxChunkBytes = 8 << 20;  // one allocation: a chunk, read or inflated
constexpr png_uint_32 kMaxAncillaryChunks = 256;

// libpng's allocator while it reads: null past kMaxChunkBytes, which libpng reports as "out of memory".
png_voidp capped_malloc(png_structp, png_alloc_size_t size) {
  return size > kMaxChunkBytes ? nullptr : std::malloc(size);
}
void capped_free(png_structp, png_voidp pointer) { std::free(pointer); }

// Reads the chunks before the image data; copies the first text with `keyword` into *text.
bool find_text(const unsigned char* data, std::size_t size, const char* keyword, std::string* text, bool* found,
               PngErrorMessage* error) {
  // A hostile file can be small and still ask for gigabytes: a chunk whose length field says 2 GB (libpng allocates
  // it before it reads it), a compressed text chunk that inflates without end, or thousands of chunks. Every
  // allocation is capped, and so is the count of chunks: far above what skinlayer writes (a few kB of JSON in one).
  png_structp png =
      png_create_read_struct_2(PNG_LIBPNG_VER_STRING, error, on_error, on_warning, nullptr, capped_malloc, capped_free);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  MemoryReader reader{data, size, 0};
  png_set_read_fn(png, &reader, read_from_memory);
  png_set_chunk_malloc_max(png, kMaxChunkBytes);
  png_set_chunk_cache_max(png, kMaxAncillaryChunks);
  png_read_info(png, info);
  png_textp texts = nullptr;
  int count = 0;
  png_get_text(png, info, &texts, &count);
  for (int k = 0; k < count && !*found; ++k) {
    if (std::strcmp(texts[k].key, keyword) != 0) continue;
    const std::size_t length = texts[k].compression > 0 ? texts[k].itxt_length : texts[k].text_length;
    text->assign(texts[k].text, length);
    *found = true;
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

std::string encode_png_rgba8(int width, int height, const std::vector<std::uint8_t>& rgba,
                             const std::vector<PngText>& texts) {
  if (width < 1 || height < 1 || rgba.size() != static_cast<std::size_t>(width) * height * 4) {
    throw std::runtime_error("the image is empty or its size does not match its pixels");
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(rgba.data() + static_cast<std::size_t>(y) * width * 4);
  }
  std::vector<::png_text> chunks(texts.size());
  for (std::size_t k = 0; k < texts.size(); ++k) {
    chunks[k] = ::png_text{};
    chunks[k].compression = PNG_ITXT_COMPRESSION_NONE;
    chunks[k].key = const_cast<png_charp>(texts[k].keyword.c_str());
    chunks[k].text = const_cast<png_charp>(texts[k].text.c_str());
    chunks[k].itxt_length = texts[k].text.size();
    chunks[k].lang = nullptr;
    chunks[k].lang_key = nullptr;
  }
  std::string bytes;
  PngErrorMessage error;
  if (!encode(width, height, rows.data(), chunks.data(), static_cast<int>(chunks.size()), &bytes, &error)) {
    throw std::runtime_error(std::string("PNG encoding failed: ") + (error.text[0] ? error.text : "out of memory"));
  }
  return bytes;
}

bool is_png(std::string_view bytes) {
  return bytes.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0;
}

std::optional<std::string> read_png_text(std::string_view bytes, std::string_view keyword) {
  if (!is_png(bytes)) throw std::runtime_error("not a PNG file");
  const std::string key(keyword);
  std::string text;
  bool found = false;
  PngErrorMessage error;
  if (!find_text(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), key.c_str(), &text, &found,
                 &error)) {
    throw std::runtime_error(std::string("damaged PNG: ") + (error.text[0] ? error.text : "out of memory"));
  }
  if (!found) return std::nullopt;
  return text;
}

}  // namespace skinlayer
