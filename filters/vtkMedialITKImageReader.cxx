#include "vtkMedialITKImageReader.h"

#include "MedialITKPlugin.h"

#include <vtkObjectFactory.h>

vtkStandardNewMacro(vtkMedialITKImageReader);

void vtkMedialITKImageReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SeriesUID: " << this->SeriesUID << "\n";
}

bool vtkMedialITKImageReader::ReadImage(const std::string& path, vtkImageData* image, std::string& error) {
  return medial::readVolumeWithITK(path, this->SeriesUID, image, error);
}
