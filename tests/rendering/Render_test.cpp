// vtkMedialScene rendered offscreen and compared with baselines (run under xvfb-run -a).
#include "ImageComparison.h"
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "vtkMedialReader.h"
#include "vtkMedialScene.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdlib>
#include <filesystem>

namespace {

using namespace medial::test;

vtkSmartPointer<vtkDataObject> read(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutputDataObject(0);
}

// Renders the scene to a PNG in the scratch directory and loads it back.
vtkSmartPointer<vtkImageData> renderScene(vtkMedialScene* scene, const std::string& name, int width,
                                          int height) {
  const std::string path = scratchDir("render-" + name) + "/" + name;
  scene->ResetCamera(static_cast<double>(width) / height);
  EXPECT_TRUE(scene->RenderToImage(path.c_str(), width, height));
  vtkSmartPointer<vtkImageData> image;
  image.TakeReference(loadPng(path));
  return image;
}

}  // namespace

TEST(Render, MeshAndSkeletonMatchBaseline) {
  MEDIAL_REQUIRE_DISPLAY();
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  ASSERT_NE(scene->AddData(read(dataPath("meshes/torus.off"))), nullptr);
  ASSERT_NE(scene->AddData(read(dataPath("skeletons/figure.vtp"))), nullptr);
  auto image = renderScene(scene, "torus-figure.png", 320, 240);
  ASSERT_NE(image, nullptr);
  EXPECT_GT(foregroundFraction(image), 0.15);
  const auto comparison = compareWithBaseline(image, "torus-figure.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(Render, SkeletonTubesFollowRadius) {
  MEDIAL_REQUIRE_DISPLAY();
  auto thin = vtkSmartPointer<vtkMedialScene>::New();
  auto thick = vtkSmartPointer<vtkMedialScene>::New();
  thin->SetSkeletonRadiusScale(0.25);
  for (vtkMedialScene* scene : {thin.GetPointer(), thick.GetPointer()})
    ASSERT_NE(scene->AddData(read(dataPath("skeletons/figure.vtp"))), nullptr);
  // Same camera for both: the thick figure's bounds are used for each.
  auto thickImage = renderScene(thick, "figure-thick.png", 240, 240);
  auto thinImage = renderScene(thin, "figure-thin.png", 240, 240);
  ASSERT_NE(thickImage, nullptr);
  ASSERT_NE(thinImage, nullptr);
  EXPECT_GT(foregroundFraction(thickImage), 1.5 * foregroundFraction(thinImage));
  const auto comparison = compareWithBaseline(thickImage, "figure.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(Render, VolumeShowsSlices) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string path = externalPath("invesalius/Cranium.inv3");
  MEDIAL_REQUIRE_FILE(path);
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  ASSERT_NE(scene->AddData(read(path)), nullptr);
  auto image = renderScene(scene, "cranium.png", 256, 192);
  ASSERT_NE(image, nullptr);
  EXPECT_GT(foregroundFraction(image), 0.2);
}

TEST(Render, EmptyDataIsRefusedWithAnError) {
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  auto errors = medial::ErrorCollector::Watch(scene);
  EXPECT_EQ(scene->AddData(vtkSmartPointer<vtkPolyData>::New()), nullptr);
  EXPECT_EQ(scene->AddData(vtkSmartPointer<vtkImageData>::New()), nullptr);
  EXPECT_EQ(scene->AddData(nullptr), nullptr);
  EXPECT_EQ(errors->GetErrors().size(), 3u);
}

TEST(Render, BaselineComparisonNoticesAMissingObject) {
  MEDIAL_REQUIRE_DISPLAY();
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  ASSERT_NE(scene->AddData(read(dataPath("meshes/torus.off"))), nullptr);  // the figure left out
  auto image = renderScene(scene, "torus-only.png", 320, 240);
  vtkSmartPointer<vtkImageData> baseline;
  baseline.TakeReference(loadPng(sourceDir() + "/tests/baselines/torus-figure.png"));
  ASSERT_NE(baseline, nullptr);
  const auto comparison = compareImages(image, baseline);
  EXPECT_FALSE(comparison.passed) << comparison.message;
}

TEST(Render, NoDisplayIsAnErrorNotAnAbort) {
  // VTK's own X window would abort the process here; the scene reports an error instead.
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  ::setenv("DISPLAY", ":9999", 1);  // nothing listens there
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  auto errors = medial::ErrorCollector::Watch(scene);
  ASSERT_NE(scene->AddData(read(dataPath("meshes/torus.off"))), nullptr);
  const std::string path = scratchDir("render-no-display") + "/never.png";
  const bool rendered = scene->RenderToImage(path.c_str(), 64, 48);
  if (saved.empty())
    ::unsetenv("DISPLAY");
  else
    ::setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_FALSE(rendered);
  EXPECT_NE(errors->Joined().find("no X display"), std::string::npos) << errors->Joined();
  EXPECT_FALSE(std::filesystem::exists(path));
}
