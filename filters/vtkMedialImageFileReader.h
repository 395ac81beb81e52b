/// \class vtkMedialImageFileReader
/// \brief Base of Medial's volume readers: reads the whole file once per file name, keeps it, and hands
/// the pipeline its extent, spacing, origin and direction (vtkImageData's direction matrix) so that
/// physical coordinates (mm) hold end to end.
///
/// Subclasses implement ReadImage. On failure: vtkErrorMacro naming the file and the problem, empty output.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;

class MEDIALFILTERS_EXPORT vtkMedialImageFileReader : public vtkImageAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: PrintSelf() prints every property.
  vtkTypeMacro(vtkMedialImageFileReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialImageFileReader();
  ~vtkMedialImageFileReader() override;
  ///@}

  /// Reads `path` into `image` (scalars, spacing, origin, direction). Returns false with `error` set.
  virtual bool ReadImage(const std::string& path, vtkImageData* image, std::string& error) = 0;

  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialImageFileReader(const vtkMedialImageFileReader&) = delete;
  void operator=(const vtkMedialImageFileReader&) = delete;

  std::string FileName;
  std::string CachedFileName;   ///< what Cache holds
  vtkMTimeType CachedTime = 0;  ///< this->GetMTime() when Cache was read
  std::string CachedError;      ///< the error of the last read, if it failed
  vtkSmartPointer<vtkImageData> Cache;
};
