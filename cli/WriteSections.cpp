#include "WriteSections.h"

#include "CommandLine.h"

#include "MedialFileNames.h"
#include "MedialProfileCsv.h"
#include "MedialTerrainFigure.h"
#include "WriteOutput.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>

#include <cstdio>
#include <fstream>
#include <functional>

namespace medial::cli {

namespace {

// Writes `path` atomically (no partial or temporary file left on failure), or throws Failure.
void writeOrFail(const std::string& path,
                 const std::function<bool(const std::string&, std::string&)>& write) {
  std::string error;
  if (!medial::writeAtomically(path, write, error)) throw Failure(path + ": " + error);
}

}  // namespace

void writeProfileCsv(vtkTable* profile, const std::string& path) {
  const std::string csv = medial::profileCsv(profile);
  if (csv.empty()) throw Failure(path + ": the centerline filter gave no profile");
  writeText(csv, path);
}

void writeTerrainPng(vtkImageData* terrain, const std::string& path) {
  const vtkSmartPointer<vtkImageData> image = medial::terrainFigure(terrain);
  if (!image) throw Failure(path + ": no wall was found along the centerline");
  writeOrFail(path, [&](const std::string& temporary, std::string& error) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetInputData(image);
    writer->SetFileName(temporary.c_str());
    writer->Write();
    if (writer->GetErrorCode() != 0) error = "cannot write the image";
    return error.empty();
  });
}

}  // namespace medial::cli
