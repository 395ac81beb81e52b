#include "WriteOutput.h"

#include "CommandLine.h"

#include "MedialErrorCollector.h"
#include "MedialFileNames.h"
#include "vtkMedialMarkupsCurveWriter.h"
#include "vtkMedialPolyDataWriter.h"
#include "vtkMedialRigWriter.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <fstream>

namespace medial::cli {

namespace {

// A writer of one polydata input with a SetFileName: writes, or throws Failure with its errors.
template <class Writer>
void writeWith(vtkPolyData* data, const std::string& path) {
  auto writer = vtkSmartPointer<Writer>::New();
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  if (!writer->Write() || errors->HasErrors()) throw Failure(errors->Joined());
}

}  // namespace

void writePolyData(vtkPolyData* data, const std::string& path) {
  writeWith<vtkMedialPolyDataWriter>(data, path);
}

void writeMarkups(vtkPolyData* centerline, const std::string& path) {
  writeWith<vtkMedialMarkupsCurveWriter>(centerline, path);
}

void requireWritableExtension(const std::string& path, const char* option) {
  if (!vtkMedialPolyDataWriter::CanWriteFile(path.c_str()))
    throw UsageError(std::string(option) + " must end in one of " + vtkMedialPolyDataWriter::GetExtensions() +
                     ": " + path);
}

void writeRig(vtkMedialRigWriter* writer, vtkPolyData* mesh, vtkPolyData* skeleton, const std::string& path) {
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(0, mesh);
  writer->SetSkeletonData(skeleton);
  if (!writer->Write() || errors->HasErrors()) throw Failure(errors->Joined());
}

void writeText(const std::string& text, const std::string& path) {
  std::string error;
  const auto write = [&text](const std::string& temporary, std::string& why) {
    std::ofstream out(temporary);
    out << text;
    if (!out.flush()) why = "cannot write the file";
    return bool(out);
  };
  if (!medial::writeAtomically(path, write, error)) throw Failure(path + ": " + error);
}

void makeOutputDirectory(const std::string& dir, const char* option) {
  if (dir.empty()) throw UsageError(std::string(option) + " needs a directory");
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) throw Failure(dir + ": cannot create the directory");
}

}  // namespace medial::cli
