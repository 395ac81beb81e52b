#include "CommandRun.h"

#include "ReadInput.h"
#include "RunFilter.h"

#include <vtkPolyData.h>

#include <cstdio>

namespace medial::cli {

CommandRun::CommandRun(const ParsedArgs& parsed) : parsed_(parsed), progress_(parsed.has("--quiet")) {}

vtkSmartPointer<vtkDataObject> CommandRun::read(const std::string& path) {
  timings_.start("read");
  return readInput(path, progress_);
}

vtkSmartPointer<vtkPolyData> CommandRun::readSurface(const std::string& path) {
  vtkSmartPointer<vtkPolyData> mesh = vtkPolyData::SafeDownCast(read(path));
  if (!mesh || mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
    throw Failure(path + ": not a surface mesh (no polygons)");
  return mesh;
}

void CommandRun::run(vtkAlgorithm* filter, vtkDataObject* data, const std::string& inputName,
                     const std::string& stage, const std::string& label) {
  timings_.start(stage);
  runFilter(filter, data, inputName, label, progress_);
}

int CommandRun::finish() {
  timings_.stop();
  if (parsed_.has("--timings")) std::printf("%s\n", timings_.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
