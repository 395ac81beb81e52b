#include "ImageComparison.h"

#include "TestPaths.h"

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace medial::test {
namespace {

void writePng(vtkImageData* image, const std::string& path) {
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}

}  // namespace

vtkImageData* loadPng(const std::string& path) {
  if (!std::filesystem::exists(path)) return nullptr;
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = vtkImageData::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

double foregroundFraction(vtkImageData* image) {
  int dims[3];
  image->GetDimensions(dims);
  const int channels = std::min(3, image->GetNumberOfScalarComponents());
  auto pixel = [&](int x, int y, int c) { return image->GetScalarComponentAsDouble(x, y, 0, c); };
  // The background is a vertical gradient: compare each pixel to the background expected on its row,
  // taken from the left-most column.
  long foreground = 0;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      double difference = 0;
      for (int c = 0; c < channels; ++c)
        difference = std::max(difference, std::abs(pixel(x, y, c) - pixel(0, y, c)));
      if (difference > 30) ++foreground;
    }
  return static_cast<double>(foreground) / (static_cast<double>(dims[0]) * dims[1]);
}

double foregroundFractionOfPng(const std::string& path) {
  vtkSmartPointer<vtkImageData> image;
  image.TakeReference(loadPng(path));
  return image ? foregroundFraction(image) : -1.0;
}

ImageComparison compareImages(vtkImageData* image, vtkImageData* baseline, int pixelTolerance,
                              double maxFractionDifferent, vtkImageData* difference) {
  ImageComparison result;
  int a[3], b[3];
  image->GetDimensions(a);
  baseline->GetDimensions(b);
  if (a[0] != b[0] || a[1] != b[1]) {
    std::ostringstream msg;
    msg << "size " << a[0] << "x" << a[1] << " differs from the baseline's " << b[0] << "x" << b[1];
    result.message = msg.str();
    return result;
  }
  const int channels =
      std::min({3, image->GetNumberOfScalarComponents(), baseline->GetNumberOfScalarComponents()});
  if (difference) {
    difference->SetDimensions(a[0], a[1], 1);
    difference->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  }
  long different = 0;
  double sum = 0;
  for (int y = 0; y < a[1]; ++y)
    for (int x = 0; x < a[0]; ++x) {
      double worst = 0;
      for (int c = 0; c < channels; ++c) {
        const double d = std::abs(image->GetScalarComponentAsDouble(x, y, 0, c) -
                                  baseline->GetScalarComponentAsDouble(x, y, 0, c));
        sum += d;
        worst = std::max(worst, d);
        if (difference) difference->SetScalarComponentFromDouble(x, y, 0, c, d);
      }
      if (worst > pixelTolerance) ++different;
    }
  const double pixels = static_cast<double>(a[0]) * a[1];
  result.meanDifference = sum / (pixels * channels);
  result.fractionDifferent = different / pixels;
  result.passed = result.fractionDifferent <= maxFractionDifferent;
  std::ostringstream msg;
  msg << 100.0 * result.fractionDifferent << " % of pixels differ by more than " << pixelTolerance
      << " (allowed " << 100.0 * maxFractionDifferent << " %), mean difference " << result.meanDifference;
  result.message = msg.str();
  return result;
}

ImageComparison compareWithBaseline(vtkImageData* image, const std::string& baselineName, int pixelTolerance,
                                    double maxFractionDifferent) {
  ImageComparison result;
  const std::string baselinePath = sourceDir() + "/tests/baselines/" + baselineName;
  const char* update = std::getenv("MEDIAL_UPDATE_BASELINES");
  if (update && std::string(update) == "1") {
    writePng(image, baselinePath);
    result.passed = true;
    result.message = "baseline written: " + baselinePath;
    return result;
  }
  vtkSmartPointer<vtkImageData> baseline;
  baseline.TakeReference(loadPng(baselinePath));
  const std::string outDir = binaryDir() + "/test-scratch/baselines";
  std::filesystem::create_directories(outDir);
  const std::string renderedPath = outDir + "/" + baselineName;
  writePng(image, renderedPath);
  if (!baseline) {
    result.message = "no baseline " + baselinePath + " (rendered image in " + renderedPath +
                     "; look at it, then run with MEDIAL_UPDATE_BASELINES=1 to accept it)";
    return result;
  }
  auto difference = vtkSmartPointer<vtkImageData>::New();
  result = compareImages(image, baseline, pixelTolerance, maxFractionDifferent, difference);
  std::ostringstream msg;
  msg << baselineName << ": " << result.message;
  if (!result.passed) {
    const std::string diffPath = outDir + "/diff-" + baselineName;
    if (difference->GetNumberOfPoints() > 0) writePng(difference, diffPath);
    msg << "; rendered: " << renderedPath << ", difference: " << diffPath;
  }
  result.message = msg.str();
  return result;
}

}  // namespace medial::test
