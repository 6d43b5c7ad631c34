// The "tensor file" container of the RGL measured-BSDF format (Dupuy & Jakob 2018), which pbrt-v4's `measured`
// material and Mitsuba 3's `measured` plugin read. Little-endian:
//   "tensor_file\0" (12 bytes), version 1, 0 (two bytes), u32 field count; then per field: u16 name length, the
//   name, u16 rank, u8 dtype, u64 absolute offset of its data, rank x u64 shape; then each field's data, row-major,
//   at its offset, which is a multiple of 8 (Mitsuba memory-maps the file).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace skinlayer {

enum class TensorType : std::uint8_t { UInt8 = 1, Float32 = 10 };  // the two dtypes the BSDF files use

struct TensorField {
  std::string name;
  TensorType type = TensorType::Float32;
  std::vector<std::uint64_t> shape;
  std::vector<std::uint8_t> bytes;  // the data, little-endian, row-major
};

TensorField float32_field(std::string name, std::vector<std::uint64_t> shape, std::span<const float> values);
TensorField uint8_field(std::string name, std::vector<std::uint64_t> shape, std::span<const std::uint8_t> values);

// The file's bytes. Throws std::invalid_argument when a field's data does not fill its shape.
std::string encode_tensor_file(std::span<const TensorField> fields);

}  // namespace skinlayer
