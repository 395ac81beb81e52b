/// \class vtkMedialITKImageReader
/// \brief Reads volumes through ITK (NIfTI .nii/.nii.gz, MetaImage .mha/.mhd, NRRD .nrrd/.nhdr, GIPL, a
/// single DICOM file, or a DICOM series directory) and bridges them to VTK with itk::VTKImageExport and
/// vtkImageImport, keeping origin, spacing and direction.
///
/// The voxel type of the file is kept (int16 CT stays int16). 2-D images are read as one-slice volumes.
/// For a directory, the DICOM series with the most slices is read (SeriesUID picks another one).
/// Multi-component (RGB, vector) images are rejected with a clear error.
#pragma once

#include "vtkMedialImageFileReader.h"

class MEDIALFILTERS_EXPORT vtkMedialITKImageReader : public vtkMedialImageFileReader {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialITKImageReader* New();
  vtkTypeMacro(vtkMedialITKImageReader, vtkMedialImageFileReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// For a DICOM directory: the series to read; empty (default) reads the series with the most files.
  vtkSetStdStringFromCharMacro(SeriesUID);
  vtkGetCharFromStdStringMacro(SeriesUID);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialITKImageReader() = default;
  ~vtkMedialITKImageReader() override = default;
  ///@}
  bool ReadImage(const std::string& path, vtkImageData* image, std::string& error) override;

 private:
  vtkMedialITKImageReader(const vtkMedialITKImageReader&) = delete;
  void operator=(const vtkMedialITKImageReader&) = delete;

  std::string SeriesUID;
};
