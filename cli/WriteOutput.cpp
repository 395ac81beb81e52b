#include "WriteOutput.h"

#include "CommandLine.h"

#include "MedialErrorCollector.h"
#include "vtkMedialPolyDataWriter.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <filesystem>

namespace medial::cli {

void writePolyData(vtkPolyData* data, const std::string& path) {
  auto writer = vtkSmartPointer<vtkMedialPolyDataWriter>::New();
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  if (!writer->Write() || errors->HasErrors()) throw Failure(errors->Joined());
}

void requireWritableExtension(const std::string& path, const char* option) {
  if (!vtkMedialPolyDataWriter::CanWriteFile(path.c_str()))
    throw UsageError(std::string(option) + " must end in one of " + vtkMedialPolyDataWriter::GetExtensions() +
                     ": " + path);
}

void makeOutputDirectory(const std::string& dir, const char* option) {
  if (dir.empty()) throw UsageError(std::string(option) + " needs a directory");
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) throw Failure(dir + ": cannot create the directory");
}

}  // namespace medial::cli
