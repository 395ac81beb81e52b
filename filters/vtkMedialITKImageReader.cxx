#include "vtkMedialITKImageReader.h"

#include <vtkImageData.h>
#include <vtkImageImport.h>
#include <vtkObjectFactory.h>

#include <itkGDCMImageIO.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageIOFactory.h>
#include <itkImageSeriesReader.h>
#include <itkVTKImageExport.h>

#include <sys/stat.h>

vtkStandardNewMacro(vtkMedialITKImageReader);

void vtkMedialITKImageReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SeriesUID: " << this->SeriesUID << "\n";
}

namespace {

// Connects an ITK image to a vtkImageImport through the callbacks of itk::VTKImageExport, then keeps a
// deep copy so that the ITK side can go away.
template <typename ImageType>
void bridgeToVtk(ImageType* itkImage, vtkImageData* out) {
  auto exporter = itk::VTKImageExport<ImageType>::New();
  exporter->SetInput(itkImage);
  auto importer = vtkSmartPointer<vtkImageImport>::New();
  importer->SetUpdateInformationCallback(exporter->GetUpdateInformationCallback());
  importer->SetPipelineModifiedCallback(exporter->GetPipelineModifiedCallback());
  importer->SetWholeExtentCallback(exporter->GetWholeExtentCallback());
  importer->SetSpacingCallback(exporter->GetSpacingCallback());
  importer->SetOriginCallback(exporter->GetOriginCallback());
  importer->SetDirectionCallback(exporter->GetDirectionCallback());
  importer->SetScalarTypeCallback(exporter->GetScalarTypeCallback());
  importer->SetNumberOfComponentsCallback(exporter->GetNumberOfComponentsCallback());
  importer->SetPropagateUpdateExtentCallback(exporter->GetPropagateUpdateExtentCallback());
  importer->SetUpdateDataCallback(exporter->GetUpdateDataCallback());
  importer->SetDataExtentCallback(exporter->GetDataExtentCallback());
  importer->SetBufferPointerCallback(exporter->GetBufferPointerCallback());
  importer->SetCallbackUserData(exporter->GetCallbackUserData());
  importer->Update();
  out->DeepCopy(importer->GetOutput());
}

std::vector<std::string> dicomSeriesFiles(const std::string& directory, const std::string& wantedUid,
                                          std::string& error) {
  auto names = itk::GDCMSeriesFileNames::New();
  names->SetUseSeriesDetails(true);
  names->SetDirectory(directory);
  const auto& uids = names->GetSeriesUIDs();
  if (uids.empty()) {
    error = "the directory holds no DICOM series";
    return {};
  }
  std::vector<std::string> best;
  for (const std::string& uid : uids) {
    if (!wantedUid.empty() && uid != wantedUid) continue;
    std::vector<std::string> files = names->GetFileNames(uid);
    if (files.size() > best.size()) best = files;
  }
  if (best.empty()) error = "no DICOM series with UID " + wantedUid;
  return best;
}

template <typename Pixel>
void readScalarImage(const std::string& path, const std::vector<std::string>& dicomFiles, vtkImageData* out) {
  using ImageType = itk::Image<Pixel, 3>;
  if (!dicomFiles.empty()) {
    auto reader = itk::ImageSeriesReader<ImageType>::New();
    reader->SetImageIO(itk::GDCMImageIO::New());
    reader->SetFileNames(dicomFiles);
    reader->Update();
    bridgeToVtk<ImageType>(reader->GetOutput(), out);
  } else {
    auto reader = itk::ImageFileReader<ImageType>::New();
    reader->SetFileName(path);
    reader->Update();
    bridgeToVtk<ImageType>(reader->GetOutput(), out);
  }
}

}  // namespace

bool vtkMedialITKImageReader::ReadImage(const std::string& path, vtkImageData* image, std::string& error) {
  try {
    struct stat status;
    const bool isDirectory = ::stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode);
    std::vector<std::string> dicomFiles;
    std::string probe = path;
    if (isDirectory) {
      dicomFiles = dicomSeriesFiles(path, this->SeriesUID, error);
      if (dicomFiles.empty()) return false;
      probe = dicomFiles.front();
    }
    auto io = itk::ImageIOFactory::CreateImageIO(probe.c_str(), itk::IOFileModeEnum::ReadMode);
    if (!io) {
      error = "no ITK reader recognises this file";
      return false;
    }
    io->SetFileName(probe);
    io->ReadImageInformation();
    if (io->GetNumberOfComponents() != 1) {
      error = "the image has " + std::to_string(io->GetNumberOfComponents()) +
              " components per voxel; Medial reads scalar volumes";
      return false;
    }
    using IOComponent = itk::IOComponentEnum;
    switch (io->GetComponentType()) {
      case IOComponent::UCHAR:
        readScalarImage<unsigned char>(path, dicomFiles, image);
        break;
      case IOComponent::CHAR:
        readScalarImage<signed char>(path, dicomFiles, image);
        break;
      case IOComponent::USHORT:
        readScalarImage<unsigned short>(path, dicomFiles, image);
        break;
      case IOComponent::SHORT:
        readScalarImage<short>(path, dicomFiles, image);
        break;
      case IOComponent::UINT:
        readScalarImage<unsigned int>(path, dicomFiles, image);
        break;
      case IOComponent::INT:
        readScalarImage<int>(path, dicomFiles, image);
        break;
      case IOComponent::FLOAT:
        readScalarImage<float>(path, dicomFiles, image);
        break;
      case IOComponent::DOUBLE:
        readScalarImage<double>(path, dicomFiles, image);
        break;
      default:
        error = std::string("unsupported voxel type ") +
                itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType());
        return false;
    }
    return true;
  } catch (const itk::ExceptionObject& e) {
    error = e.GetDescription();
    return false;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}
