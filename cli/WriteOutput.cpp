#include "WriteOutput.h"

#include "CommandLine.h"

#include "MedialErrorCollector.h"
#include "vtkMedialPolyDataWriter.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

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

}  // namespace medial::cli
