// index.html for a folder of figures: every PNG with its title, caption and a link to its CSV.
#pragma once

#include <filesystem>
#include <vector>

#include "app/figures/figure_builder.h"
#include "app/figures/figure_set.h"

namespace skinlayer::figures {

// Writes dir/index.html; each <img> states its PNG's width and height (sizes[k] for figures[k]). Throws
// std::runtime_error if it cannot be written.
void write_figure_index(const std::vector<FigureSpec>& figures, const std::vector<FigureSize>& sizes,
                        const std::filesystem::path& dir);

}  // namespace skinlayer::figures
