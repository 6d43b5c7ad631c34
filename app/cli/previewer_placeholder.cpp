#include "app/cli/previewer_placeholder.h"

#include "app/cli/errors.h"

namespace skinlayer::cli {

int run_previewer_placeholder(std::ostream& err) {
  err << "skinlayer: the interactive previewer is not built yet; use `skinlayer eval` or `skinlayer albedo` "
         "(see skinlayer --help)\n";
  return kExitUsage;
}

}  // namespace skinlayer::cli
