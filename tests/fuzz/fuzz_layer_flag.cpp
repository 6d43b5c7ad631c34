// Fuzz target: one --layer value (app/cli/layer_flag.h). The first byte picks the layer's place (1-4) and whether
// the command takes RGB albedos; the rest is the value. A layer that reads is in range, and its formatted spec reads
// back as the same layer.
#include "app/cli/errors.h"
#include "app/cli/layer_flag.h"
#include "tests/fuzz/fuzz_target.h"

using namespace skinlayer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int place = 1 + (data[0] & 3);
  const bool rgb_albedo = (data[0] & 4) != 0;
  const std::string_view text = fuzz::input_bytes(data + 1, size - 1);
  cli::LayerSpec spec;
  if (fuzz::refused_cleanly<ParameterError, cli::UsageError>(
          [&] { spec = cli::parse_layer_spec(text, place, rgb_albedo); })) {
    return 0;
  }
  fuzz::require(place > 1 || !spec.interface, "the first layer read an interface above it");
  StackedLayer layer{spec.tau, spec.albedo[0], spec.g, spec.interface};
  const std::string formatted = format_layer_spec(layer, spec.albedo);
  cli::LayerSpec again;
  if (fuzz::refused_cleanly<ParameterError, cli::UsageError>(
          [&] { again = cli::parse_layer_spec(formatted, place, rgb_albedo); })) {
    fuzz::fuzz_failure("a layer that was read does not read back once formatted: " + formatted);
  }
  fuzz::require(
      again.tau == spec.tau && again.albedo == spec.albedo && again.g == spec.g && again.interface == spec.interface,
      "a formatted layer reads back as another: " + formatted);
  return 0;
}
