#include "RigOptions.h"

#include "FilterOptions.h"
#include "HelpText.h"

#include "rig/RigExport.h"
#include "vtkMedialRigWriter.h"

#include <vtkSmartPointer.h>

#include <limits>

namespace medial::cli {

const std::vector<std::string>& rigWriterOptionNames() {
  static const std::vector<std::string> names = {"--up-axis", "--scale", "--max-influences"};
  return names;
}

std::string rigWriterHelp() {
  const auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  return std::string() + "  --up-axis x|y|z|-x|-y|-z  the mesh's up axis (default " + writer->GetUpAxis() +
         ", glTF's; z for most scans\n"
         "                            and CAD): the rig is turned so that the character stands in Blender\n"
         "  --scale F                 mesh units to metres in the rig (default " +
         number(writer->GetScale()) +
         "; 0.01 for centimetres)\n"
         "  --max-influences N        most bones per vertex (default " +
         number(writer->GetMaxInfluences()) + ")\n";
}

void applyRigWriterOptions(const ParsedArgs& parsed, vtkMedialRigWriter* writer) {
  MEDIAL_OPTION(parsed, "--max-influences", writer, MaxInfluences);
  if (parsed.has("--up-axis")) {
    Eigen::Matrix3d turn;
    const std::string axis = parsed.value("--up-axis");
    if (!upAxisRotation(axis, turn))
      throw UsageError("--up-axis must be one of x, y, z, -x, -y, -z: " + axis);
    writer->SetUpAxis(axis.c_str());
  }
  setNumberFromOption(parsed, "--scale", 0, std::numeric_limits<double>::max(), false, [&](double scale) {
    if (!(scale > 0)) throw UsageError("--scale must be a positive number, got 0");
    writer->SetScale(scale);
  });
}

}  // namespace medial::cli
