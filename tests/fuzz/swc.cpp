// Fuzz target: vtkMedialSWCReader on any bytes. It must report an error or give a polydata, never crash, hang
// or allocate without bound.
#include "FuzzFile.h"
#include "vtkMedialSWCReader.h"

#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vtkObject::GlobalWarningDisplayOff();
  const std::string path = medial::fuzz::writeInput(data, size, ".swc");
  auto reader = vtkSmartPointer<vtkMedialSWCReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return 0;
}
