#include "vtkMedialPolyDataWriter.h"

#include "MedialErrorCollector.h"
#include "MedialFileNames.h"
#include "vtkMedialSWCWriter.h"

#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkOBJWriter.h>
#include <vtkObjectFactory.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdio>
#include <fstream>
#include <functional>

vtkStandardNewMacro(vtkMedialPolyDataWriter);

void vtkMedialPolyDataWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}

bool vtkMedialPolyDataWriter::CanWriteFile(const char* fileName) {
  if (!fileName) return false;
  const std::string e = medial::fileExtension(fileName);
  return e == ".vtp" || e == ".vtk" || e == ".obj" || e == ".ply" || e == ".stl" || e == ".swc";
}

int vtkMedialPolyDataWriter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkMedialPolyDataWriter::WriteData() {
  this->SetErrorCode(vtkErrorCode::NoError);
  if (this->FileName.empty()) {
    vtkErrorMacro(<< "no file name given");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  const std::string extension = medial::fileExtension(this->FileName);
  if (!CanWriteFile(this->FileName.c_str())) {
    vtkErrorMacro(<< this->FileName << ": cannot write '" << extension << "' files (use one of "
                  << GetExtensions() << ")");
    this->SetErrorCode(vtkErrorCode::UnrecognizedFileTypeError);
    return;
  }
  std::string error;
  // WriteTo reports its own errors; `error` then stays empty.
  const auto write = [&](const std::string& temporary, std::string&) {
    return this->WriteTo(temporary, extension);
  };
  if (!medial::writeAtomically(this->FileName, write, error)) {
    if (!error.empty()) vtkErrorMacro(<< error);
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

bool vtkMedialPolyDataWriter::WriteTo(const std::string& path, const std::string& extension) {
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (!input) {
    vtkErrorMacro(<< this->FileName << ": no polydata to write");
    return false;
  }
  // vtkXMLPolyDataWriter is no vtkWriter: keep the algorithm and how to make it write.
  vtkSmartPointer<vtkAlgorithm> writer;
  std::function<int()> write;
  std::string ioError;  // a failure of our own writing
  if (extension == ".vtp") {
    // Written to memory, then to the file by us: VTK 9.1's XML writer crashes (a double free in
    // DeletePositionArrays) when the disk fills up in the middle of a piece.
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->WriteToOutputStringOn();
    w->SetDataModeToBinary();
    w->SetCompressorTypeToZLib();
    writer = w;
    write = [w, path, &ioError] {
      if (!w->Write()) return 0;
      std::ofstream out(path, std::ios::binary);
      const std::string& bytes = w->GetOutputString();
      out.write(bytes.data(), std::streamsize(bytes.size()));
      if (!out.flush()) ioError = out.is_open() ? "write failed (disk full?)" : "cannot create the file";
      return ioError.empty() ? 1 : 0;
    };
  } else if (extension == ".vtk") {
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    writer = w;
    write = [w] { return w->Write(); };
  } else if (extension == ".obj") {
    auto w = vtkSmartPointer<vtkOBJWriter>::New();
    w->SetFileName(path.c_str());
    writer = w;
    write = [w] { return w->Write(); };
  } else if (extension == ".ply") {
    auto w = vtkSmartPointer<vtkPLYWriter>::New();
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    writer = w;
    write = [w] { return w->Write(); };
  } else if (extension == ".stl") {
    auto w = vtkSmartPointer<vtkSTLWriter>::New();  // STL holds triangles only
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
    triangles->SetInputData(input);
    triangles->Update();
    w->SetInputData(triangles->GetOutput());
    writer = w;
    write = [w] { return w->Write(); };
  } else {
    auto w = vtkSmartPointer<vtkMedialSWCWriter>::New();
    w->SetFileName(path.c_str());
    writer = w;
    write = [w] { return w->Write(); };
  }
  if (!writer->GetInputDataObject(0, 0)) writer->SetInputDataObject(input);
  auto errors = medial::ErrorCollector::Watch(writer);
  const int ok = write();
  if (!ok || errors->HasErrors() || writer->GetErrorCode() != vtkErrorCode::NoError) {
    std::string why = errors->Joined();
    if (why.empty()) why = ioError;
    if (why.empty()) why = vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    // Name the file the user asked for, not the temporary one.
    for (size_t at; (at = why.find(path)) != std::string::npos;) why.replace(at, path.size(), this->FileName);
    vtkErrorMacro(<< (why.rfind(this->FileName, 0) == 0 ? why : this->FileName + ": " + why));
    return false;
  }
  return true;
}
