// Command-line options of the picture outputs (PNG view, SVG scale), shared by every verb that
// writes scenes.
#pragma once

#include "io/output.h"

namespace CLI {
class App;
}

namespace insula::cli {

void add_view_options(CLI::App& command, io::OutputOptions& output);

}  // namespace insula::cli
