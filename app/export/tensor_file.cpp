#include "app/export/tensor_file.h"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace skinlayer {
namespace {

static_assert(std::endian::native == std::endian::little, "the tensor file is little-endian");

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::size_t element_size(TensorType type) { return type == TensorType::Float32 ? 4 : 1; }

}  // namespace

TensorField float32_field(std::string name, std::vector<std::uint64_t> shape, std::span<const float> values) {
  TensorField field{std::move(name), TensorType::Float32, std::move(shape), {}};
  field.bytes.resize(values.size() * sizeof(float));
  if (!values.empty()) std::memcpy(field.bytes.data(), values.data(), field.bytes.size());
  return field;
}

TensorField uint8_field(std::string name, std::vector<std::uint64_t> shape, std::span<const std::uint8_t> values) {
  return TensorField{std::move(name), TensorType::UInt8, std::move(shape), {values.begin(), values.end()}};
}

std::string encode_tensor_file(std::span<const TensorField> fields) {
  std::size_t header = 12 + 2 + 4;
  for (const TensorField& f : fields) {
    std::uint64_t count = 1;
    for (const std::uint64_t n : f.shape) count *= n;
    if (count * element_size(f.type) != f.bytes.size()) {
      throw std::invalid_argument("tensor field " + f.name + ": " + std::to_string(f.bytes.size()) +
                                  " bytes do not fill its shape");
    }
    header += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
  }
  const auto aligned = [](std::size_t offset) { return (offset + 7) / 8 * 8; };
  std::string out;
  out.append("tensor_file", 12);  // with its terminating zero
  out.push_back(1);
  out.push_back(0);
  put(out, static_cast<std::uint32_t>(fields.size()));
  std::size_t offset = aligned(header);
  for (const TensorField& f : fields) {
    put(out, static_cast<std::uint16_t>(f.name.size()));
    out += f.name;
    put(out, static_cast<std::uint16_t>(f.shape.size()));
    put(out, static_cast<std::uint8_t>(f.type));
    put(out, static_cast<std::uint64_t>(offset));
    for (const std::uint64_t n : f.shape) put(out, n);
    offset = aligned(offset + f.bytes.size());
  }
  for (const TensorField& f : fields) {
    out.resize(aligned(out.size()), '\0');
    out.append(reinterpret_cast<const char*>(f.bytes.data()), f.bytes.size());
  }
  return out;
}

}  // namespace skinlayer
