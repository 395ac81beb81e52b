// libMedialITKIO: Medial's volume reading through ITK (NIfTI, MetaImage, NRRD, GIPL, DICOM files and
// series), a plugin of its own that vtkMedialITKImageReader loads on first use. ITK and GDCM cost every
// process that loads them time at start (GDCM fills its dictionaries), which mesh and skeleton commands,
// run thousands of times by `medial batch`, never need. The function's contract is MedialITKPlugin.h's.
#include "MedialFileNames.h"
#include "MedialITKPlugin.h"

#include <vtkImageData.h>
#include <vtkAOSDataArrayTemplate.h>
#include <vtkDataArray.h>
#include <vtkTypeTraits.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <itkGDCMImageIO.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageIOFactory.h>
#include <itkImageSeriesReader.h>
#include <itkVTKImageExport.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace {

// Hands the ITK image's voxels to `out` without a copy: the pixel container lets go of its buffer (which
// ITK allocated with new[]) and a VTK array takes it over (freed with delete[]). The frame is ITK's: extent
// from the region's index, origin, spacing and direction as ITK has them (VTK 9's image data applies the
// direction the same way). A CT of 210 MB no longer needs 420 MB while it is read.
template <typename ImageType>
void adoptIntoVtk(ImageType* image, vtkImageData* out) {
  using Pixel = typename ImageType::PixelType;
  const auto region = image->GetBufferedRegion();
  const auto index = region.GetIndex();
  const auto size = region.GetSize();
  out->SetExtent(int(index[0]), int(index[0] + size[0]) - 1, int(index[1]), int(index[1] + size[1]) - 1,
                 int(index[2]), int(index[2] + size[2]) - 1);
  out->SetSpacing(image->GetSpacing()[0], image->GetSpacing()[1], image->GetSpacing()[2]);
  out->SetOrigin(image->GetOrigin()[0], image->GetOrigin()[1], image->GetOrigin()[2]);
  double direction[9];
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) direction[3 * r + c] = image->GetDirection()(r, c);
  out->SetDirectionMatrix(direction);
  auto* container = image->GetPixelContainer();
  const vtkIdType count = vtkIdType(container->Size());
  container->SetContainerManageMemory(false);
  // The concrete array class of the type (vtkShortArray for int16...), as VTK's own readers give.
  vtkSmartPointer<vtkAOSDataArrayTemplate<Pixel>> scalars;
  scalars.TakeReference(vtkAOSDataArrayTemplate<Pixel>::SafeDownCast(
      vtkDataArray::CreateDataArray(vtkTypeTraits<Pixel>::VTKTypeID())));
  scalars->SetName("scalars");  // as vtkImageImport named them
  scalars->SetArray(container->GetImportPointer(), count, 0,
                    vtkAOSDataArrayTemplate<Pixel>::VTK_DATA_ARRAY_DELETE);
  out->GetPointData()->SetScalars(scalars);
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
    adoptIntoVtk<ImageType>(reader->GetOutput(), out);
  } else {
    auto reader = itk::ImageFileReader<ImageType>::New();
    reader->SetFileName(path);
    reader->Update();
    adoptIntoVtk<ImageType>(reader->GetOutput(), out);
  }
}

// Bytes of a file (-1 when it cannot be read).
double fileBytes(const std::string& path) {
  struct stat status;
  return ::stat(path.c_str(), &status) == 0 ? double(status.st_size) : -1.0;
}

// The uncompressed file that must hold the voxels of `path`, when the format says so plainly: a .nii
// file, or a MetaImage whose header names its raw data (LOCAL: the file itself) without compression.
// Empty when the voxels may be compressed or stored elsewhere.
std::string rawDataFile(const std::string& path) {
  const std::string extension = medial::fileExtension(path);
  if (extension == ".nii") return path;
  if (extension != ".mha" && extension != ".mhd") return {};
  std::ifstream header(path);
  std::string line, dataFile;
  bool compressed = false;
  while (std::getline(header, line) && line.size() < 4096) {
    const size_t equals = line.find('=');
    if (equals == std::string::npos) continue;
    std::string key = line.substr(0, equals), value = line.substr(equals + 1);
    key.erase(key.find_last_not_of(" \t") + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t\r") + 1);
    if (key == "CompressedData") compressed = value == "True" || value == "true";
    if (key == "ElementDataFile") {
      dataFile = value;
      break;  // the voxels follow
    }
  }
  if (compressed || dataFile.empty() || dataFile.find(' ') != std::string::npos) return {};  // lists of files
  if (dataFile == "LOCAL") return path;
  const size_t slash = path.find_last_of('/');
  return (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) + dataFile;
}

// "4.0 GB", "12.5 MB", "100 bytes".
std::string sizeText(double bytes) {
  char text[64];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  else if (bytes >= 1e6)
    std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
  else
    std::snprintf(text, sizeof text, "%.0f bytes", bytes);
  return text;
}

// Refuses a header that claims more voxels than its file holds (a truncated download, a hostile header)
// or than this machine's memory, before ITK allocates them.
bool voxelsFit(itk::ImageIOBase* io, const std::string& path, size_t files, std::string& error) {
  const double bytes = double(io->GetImageSizeInBytes()) * double(files);
  const double memory = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGESIZE));
  if (memory > 0 && bytes > memory) {
    error = "the header claims " + sizeText(bytes) + " of voxels, more than this machine's " +
            sizeText(memory) + " of memory";
    return false;
  }
  const std::string raw = files == 1 ? rawDataFile(path) : std::string();
  const double held = raw.empty() ? -1.0 : fileBytes(raw);
  if (!raw.empty() && held < bytes) {
    error = "the header claims " + sizeText(bytes) + " of voxels, the file " +
            (raw == path ? "" : raw + " ") + "holds " + sizeText(std::max(0.0, held));
    return false;
  }
  return true;
}

// A slice of an uncompressed DICOM series that is shorter than its voxels (a truncated copy) is an error:
// GDCM reads it without complaint, as garbage. Compressed transfer syntaxes may be shorter: not checked.
// The transfer syntax UID of a DICOM file: element (0002,0010) of its file meta information, which the
// standard always writes in explicit VR little endian after the 128-byte preamble and "DICM" (ITK's
// dictionary leaves group 0002 out). Empty when not found.
std::string dicomTransferSyntax(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  const size_t at = head.find(std::string("\x02\x00\x10\x00UI", 6));
  if (at == std::string::npos || at + 8 > head.size()) return {};
  const size_t length = size_t(uint8_t(head[at + 6])) | size_t(uint8_t(head[at + 7])) << 8;
  std::string uid = head.substr(at + 8, length);
  uid.erase(uid.find_last_not_of(std::string(" \0", 2)) + 1);
  return uid;
}

bool slicesComplete(itk::ImageIOBase* io, const std::vector<std::string>& files, std::string& error) {
  const std::string syntax = dicomTransferSyntax(files.front());
  if (syntax != "1.2.840.10008.1.2" && syntax != "1.2.840.10008.1.2.1" && syntax != "1.2.840.10008.1.2.2")
    return true;
  const double slice = double(io->GetImageSizeInBytes());
  for (const std::string& file : files)
    if (fileBytes(file) < slice) {
      error = file + ": the slice is truncated (" + sizeText(std::max(0.0, fileBytes(file))) +
              ", its voxels alone need " + sizeText(slice) + ")";
      return false;
    }
  return true;
}

}  // namespace

// The entry point vtkMedialITKImageReader finds with dlsym (filters/MedialITKPlugin.h).
extern "C" __attribute__((visibility("default"))) bool medialReadVolumeWithITK(const std::string& path,
                                                                               const std::string& seriesUid,
                                                                               vtkImageData* image,
                                                                               std::string& error) {
  try {
    struct stat status;
    const bool isDirectory = ::stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode);
    std::vector<std::string> dicomFiles;
    std::string probe = path;
    if (isDirectory) {
      dicomFiles = dicomSeriesFiles(path, seriesUid, error);
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
    if (!voxelsFit(io, path, std::max<size_t>(1, dicomFiles.size()), error)) return false;
    if (!dicomFiles.empty() && !slicesComplete(io, dicomFiles, error)) return false;
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
