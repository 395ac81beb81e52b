// The rig writer's options that `medial skeleton --rig` and `medial rig` share: --up-axis, --scale and
// --max-influences, their help lines and their checks.
#pragma once

#include "CommandLine.h"

#include <string>
#include <vector>

class vtkMedialRigWriter;

namespace medial::cli {

// The option names that take a value.
const std::vector<std::string>& rigWriterOptionNames();

// Their lines of --help, with a fresh writer's defaults.
std::string rigWriterHelp();

// Sets the writer's properties from the options given; an unknown axis or a scale that is not positive is a
// UsageError.
void applyRigWriterOptions(const ParsedArgs& parsed, vtkMedialRigWriter* writer);

}  // namespace medial::cli
