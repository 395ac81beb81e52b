// Compares a rendered image with a baseline in tests/baselines/ within a tolerance; on failure writes the
// rendered image and a difference image next to the test's scratch files, and says where.
#pragma once

#include <string>

class vtkImageData;

namespace medial::test {

struct ImageComparison {
  bool passed = false;
  double meanDifference = 0;     // mean absolute difference per channel, 0..255
  double fractionDifferent = 0;  // share of pixels where a channel differs by more than pixelTolerance
  std::string message;
};

// Passes when at most `maxFractionDifferent` of the pixels differ by more than `pixelTolerance` (0..255) in
// some channel. With MEDIAL_UPDATE_BASELINES=1 in the environment, (re)writes the baseline instead.
ImageComparison compareWithBaseline(vtkImageData* image, const std::string& baselineName,
                                    int pixelTolerance = 40, double maxFractionDifferent = 0.01);

// Compares two images of the same size (no files written). `difference`, when given, receives the
// per-channel absolute difference.
ImageComparison compareImages(vtkImageData* image, vtkImageData* reference, int pixelTolerance = 40,
                              double maxFractionDifferent = 0.01, vtkImageData* difference = nullptr);

// Loads a PNG; null when unreadable.
vtkImageData* loadPng(const std::string& path);  // caller owns (Delete) the result

// Pixels whose colour differs from the top-left pixel's and the bottom-left's (the background gradient
// ends), as a share of all pixels: a blank render gives ~0.
double foregroundFraction(vtkImageData* image);
// The same for a PNG file; -1 when it cannot be read.
double foregroundFractionOfPng(const std::string& path);

}  // namespace medial::test
