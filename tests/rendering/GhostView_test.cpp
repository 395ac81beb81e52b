// vtkMedialGhostPass: objects of interest inside occluders, rendered offscreen (run under xvfb-run -a).
#include "ImageComparison.h"
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialGhostPass.h"
#include "vtkMedialReader.h"
#include "vtkMedialScene.h"

#include <vtkActor.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProp3D.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkRTAnalyticSource.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace {

using namespace medial::test;

vtkSmartPointer<vtkPolyData> box(double side) {
  auto source = vtkSmartPointer<vtkCubeSource>::New();
  source->SetXLength(side);
  source->SetYLength(side);
  source->SetZLength(side);
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkPolyData> sphere(double radius, double x = 0, double y = 0, double z = 0) {
  auto source = vtkSmartPointer<vtkSphereSource>::New();
  source->SetRadius(radius);
  source->SetCenter(x, y, z);
  source->SetThetaResolution(48);
  source->SetPhiResolution(32);
  source->Update();
  return source->GetOutput();
}

// Pixel counts by hue: the scene's palette draws the first object ivory, the second red, the third blue.
struct Hues {
  double red = 0;           // share of pixels that are clearly red
  double blue = 0;          // bluish: blue, or blue seen through a red ghost (violet)
  double ivory = 0;         // warm and light: the occluder
  double meanRedGreen = 0;  // mean green channel over the red pixels (how much occluder tint is on them)
};

Hues countHues(vtkImageData* image) {
  Hues hues;
  int dims[3];
  image->GetDimensions(dims);
  const int components = image->GetNumberOfScalarComponents();
  const auto* pixel = static_cast<const unsigned char*>(image->GetScalarPointer());
  const double total = static_cast<double>(dims[0]) * dims[1];
  double redGreenSum = 0;
  for (int i = 0; i < dims[0] * dims[1]; ++i, pixel += components) {
    const double r = pixel[0], g = pixel[1], b = pixel[2];
    if (r > 80 && r > 1.6 * g && r > 1.6 * b) {
      hues.red += 1;
      redGreenSum += g;
    } else if (b > 60 && b > g + 30 && b > 0.8 * r) {
      hues.blue += 1;
    } else if (r > 90 && r >= g && g > b && r - b > 15) {
      hues.ivory += 1;
    }
  }
  hues.meanRedGreen = hues.red > 0 ? redGreenSum / hues.red : 0;
  hues.red /= total;
  hues.blue /= total;
  hues.ivory /= total;
  return hues;
}

// Mean RGB of the (2 half + 1)^2 pixels around the image's centre.
std::array<double, 3> meanColorAtCentre(vtkImageData* image, int half) {
  int dims[3];
  image->GetDimensions(dims);
  std::array<double, 3> sum = {0, 0, 0};
  int count = 0;
  for (int y = dims[1] / 2 - half; y <= dims[1] / 2 + half; ++y)
    for (int x = dims[0] / 2 - half; x <= dims[0] / 2 + half; ++x, ++count)
      for (int c = 0; c < 3; ++c) sum[c] += image->GetScalarComponentAsDouble(x, y, 0, c);
  for (double& value : sum) value /= count;
  return sum;
}

vtkSmartPointer<vtkImageData> render(vtkMedialScene* scene, const std::string& name, double azimuth = 30) {
  const int width = 320, height = 240;
  // One folder per test and picture: tests run in parallel and several render a picture of the same name
  // (two of them once removed each other's folder between the write and the rename).
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string path = scratchDir("ghost-" + test + "-" + name) + "/" + name;
  scene->ResetCamera(static_cast<double>(width) / height, azimuth, 20);
  EXPECT_TRUE(scene->RenderToImage(path.c_str(), width, height));
  vtkSmartPointer<vtkImageData> image;
  image.TakeReference(loadPng(path));
  return image;
}

// A 4-unit box (ivory) around a sphere of radius 1 (red), the sphere an object of interest.
struct BoxAndSphere {
  vtkSmartPointer<vtkMedialScene> scene = vtkSmartPointer<vtkMedialScene>::New();
  vtkProp3D* interest = nullptr;
  explicit BoxAndSphere(int mode) {
    scene->AddData(box(4.0));
    interest = scene->AddData(sphere(1.0));
    scene->SetImportance(interest, 1.0);
    scene->GetGhostPass()->SetMode(mode);
  }
};

}  // namespace

TEST(GhostView, OffLeavesTheInterestObjectHidden) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere off(vtkMedialGhostPass::Off);
  auto image = render(off.scene, "off.png");
  ASSERT_NE(image, nullptr);
  const Hues hues = countHues(image);
  EXPECT_LT(hues.red, 0.0005);
  EXPECT_GT(hues.ivory, 0.2);
}

TEST(GhostView, GhostShowsTheInterestObjectAndKeepsTheOccluder) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere off(vtkMedialGhostPass::Off), ghost(vtkMedialGhostPass::Ghost);
  auto offImage = render(off.scene, "off.png");
  auto image = render(ghost.scene, "ghost.png");
  ASSERT_NE(image, nullptr);
  const Hues before = countHues(offImage), after = countHues(image);
  EXPECT_GT(after.red, 0.03);  // the sphere covers ~6 % of the image
  // The occluder still covers the rest: what it lost is about what the sphere took.
  EXPECT_GT(after.ivory, before.ivory - after.red - 0.02);
  EXPECT_NEAR(foregroundFraction(image), foregroundFraction(offImage), 0.01);
  EXPECT_EQ(ghost.scene->GetGhostPass()->GetLastInterestCount(), 1);
  const auto comparison = compareWithBaseline(image, "ghost-box-sphere.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(GhostView, CutawayRemovesTheOccluderOverTheInterestObject) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere ghost(vtkMedialGhostPass::Ghost), cutaway(vtkMedialGhostPass::Cutaway);
  auto ghostImage = render(ghost.scene, "ghost.png");
  auto image = render(cutaway.scene, "cutaway.png");
  ASSERT_NE(image, nullptr);
  const Hues ghostHues = countHues(ghostImage), cutawayHues = countHues(image);
  EXPECT_GT(cutawayHues.red, 0.03);
  // Over the sphere no occluder colour is left: the red pixels carry less green than the ghost's.
  EXPECT_LT(cutawayHues.meanRedGreen, ghostHues.meanRedGreen - 5);
  const auto comparison = compareWithBaseline(image, "cutaway-box-sphere.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(GhostView, InterestObjectStaysVisibleAfterTheCameraTurns) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere ghost(vtkMedialGhostPass::Ghost);
  for (double azimuth : {30.0, 120.0, 210.0}) {
    auto image = render(ghost.scene, "turn" + std::to_string(static_cast<int>(azimuth)) + ".png", azimuth);
    ASSERT_NE(image, nullptr);
    EXPECT_GT(countHues(image).red, 0.03) << "azimuth " << azimuth;
  }
}

TEST(GhostView, GradualImportanceShowsBothNestedObjects) {
  MEDIAL_REQUIRE_DISPLAY();
  // Box (ivory) around a large sphere (red, importance 0.25) around a small one (blue, importance 1).
  auto makeScene = [](int conflict) {
    auto scene = vtkSmartPointer<vtkMedialScene>::New();
    scene->AddData(box(4.0));
    scene->SetImportance(scene->AddData(sphere(1.4)), 0.25);
    scene->SetImportance(scene->AddData(sphere(0.7, 0.1, 0.1, 0.2)), 1.0);
    scene->GetGhostPass()->SetConflict(conflict);
    return scene;
  };
  auto gradual = render(makeScene(vtkMedialGhostPass::GradualImportance), "gradual.png");
  auto depth = render(makeScene(vtkMedialGhostPass::DepthSorting), "depth.png");
  ASSERT_NE(gradual, nullptr);
  ASSERT_NE(depth, nullptr);
  // Gradual: the blue sphere shows through the red one at the centre; depth sorting: the nearer red
  // sphere hides it. Both keep the red sphere visible around it.
  const auto gradualCentre = meanColorAtCentre(gradual, 8), depthCentre = meanColorAtCentre(depth, 8);
  EXPECT_GT(gradualCentre[2] - depthCentre[2], 25.0);
  EXPECT_GT(depthCentre[0], depthCentre[2] + 60.0);
  EXPECT_GT(countHues(gradual).red, 0.02);
  EXPECT_GT(countHues(depth).red, 0.05);
  const auto comparison = compareWithBaseline(gradual, "ghost-gradual.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(GhostView, ShadersAreRebuiltWhenTheObjectsOfInterestOrLayersChange) {
  MEDIAL_REQUIRE_DISPLAY();
  // Objects of interest write depth in their shaders, context props do not (unless LayeredGhosts): the
  // pass's shader-stage time must move when either changes, so that VTK's mappers rebuild them.
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  scene->AddData(box(4.0));
  vtkProp3D* large = scene->AddData(sphere(1.4));
  vtkProp3D* small = scene->AddData(sphere(0.7, 0.1, 0.1, 0.2));
  scene->SetImportance(small, 1.0);
  vtkMedialGhostPass* pass = scene->GetGhostPass();
  ASSERT_NE(render(scene, "stage-1.png"), nullptr);
  const vtkMTimeType first = pass->GetShaderStageMTime();
  ASSERT_NE(render(scene, "stage-2.png"), nullptr);
  EXPECT_EQ(pass->GetShaderStageMTime(), first);  // nothing changed: no rebuild
  scene->SetImportance(large, 0.25);
  auto late = render(scene, "stage-3.png");
  ASSERT_NE(late, nullptr);
  const vtkMTimeType second = pass->GetShaderStageMTime();
  EXPECT_GT(second, first);
  pass->SetLayeredGhosts(true);
  EXPECT_GT(pass->GetShaderStageMTime(), second);
  pass->SetLayeredGhosts(false);
  // And the picture is the one of the scene built with its importances from the start.
  const auto comparison = compareWithBaseline(late, "ghost-gradual.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(GhostView, LayeredGhostsShowEveryOccludingLayer) {
  MEDIAL_REQUIRE_DISPLAY();
  // Two nested boxes (ivory, then red) in front of the sphere (blue): the outer one is drawn first.
  // Without layers, its ghosted fragments keep their depth and hide the inner box's; with layers, both
  // boxes tint the sphere.
  auto centreOf = [](bool layered) {
    auto scene = vtkSmartPointer<vtkMedialScene>::New();
    scene->AddData(box(4.0));
    scene->AddData(box(3.0));
    scene->SetImportance(scene->AddData(sphere(1.0)), 1.0);
    scene->GetGhostPass()->SetLayeredGhosts(layered);
    auto image = render(scene, layered ? "layered.png" : "unlayered.png");
    EXPECT_NE(image, nullptr);
    const auto centre = meanColorAtCentre(image, 8);
    EXPECT_GT(centre[2], centre[0] + 20);  // the sphere shows either way
    return centre;
  };
  const auto single = centreOf(false), layered = centreOf(true);
  std::printf("centre without layers %.0f %.0f %.0f, with %.0f %.0f %.0f\n", single[0], single[1], single[2],
              layered[0], layered[1], layered[2]);
  EXPECT_GT(single[2] - layered[2], 15.0);  // less of the blue sphere: two layers over it
  EXPECT_GT(layered[0] - single[0], 5.0);   // the inner, red box among them
}

TEST(GhostView, SkeletonShowsThroughItsMesh) {
  MEDIAL_REQUIRE_DISPLAY();
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(dataPath("meshes/torus.off").c_str());
  auto skeleton = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  skeleton->SetInputConnection(reader->GetOutputPort());
  skeleton->Update();
  ASSERT_GT(skeleton->GetOutput()->GetNumberOfLines(), 0);

  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  scene->SetSkeletonRadiusScale(0.5);
  scene->AddData(reader->GetOutput());
  vtkProp3D* bones = scene->AddData(skeleton->GetOutput());
  auto plain = render(scene, "torus-plain.png");
  scene->SetImportance(bones, 1.0);
  auto ghosted = render(scene, "torus-ghost.png");
  ASSERT_NE(plain, nullptr);
  ASSERT_NE(ghosted, nullptr);
  EXPECT_LT(countHues(plain).red, 0.002);
  EXPECT_GT(countHues(ghosted).red, 0.02);
  const auto comparison = compareWithBaseline(ghosted, "ghost-torus-skeleton.png");
  EXPECT_TRUE(comparison.passed) << comparison.message;
}

TEST(GhostView, AVolumeRenderingIsGhostedAndCutAwayLikeAnOccluder) {
  MEDIAL_REQUIRE_DISPLAY();
  // A ray-cast volume (grey to ivory, VTK's analytic wavelet over 81^3 voxels, full-range preset) around
  // a red sphere of interest: hidden without the pass, tinted through the ghost, clear in the cutaway.
  auto wavelet = vtkSmartPointer<vtkRTAnalyticSource>::New();
  wavelet->SetWholeExtent(-40, 40, -40, 40, -40, 40);
  wavelet->Update();
  auto centreOf = [&](int mode, const std::string& name) {
    auto scene = vtkSmartPointer<vtkMedialScene>::New();
    scene->SetVolumeStyle(3);
    EXPECT_NE(scene->AddData(wavelet->GetOutput()), nullptr);
    vtkProp3D* ball = scene->AddData(sphere(12.0));
    vtkActor::SafeDownCast(ball)->GetProperty()->SetColor(1.0, 0.1, 0.1);
    scene->SetImportance(ball, 1.0);
    scene->GetGhostPass()->SetMode(mode);
    auto image = render(scene, name);
    EXPECT_NE(image, nullptr);
    if (mode == vtkMedialGhostPass::Cutaway) {
      const auto comparison = compareWithBaseline(image, "ghost-volume-cutaway.png");
      EXPECT_TRUE(comparison.passed) << comparison.message;
    }
    const auto c = meanColorAtCentre(image, 6);
    return c[0] - c[2];  // the sphere: red far above blue; the volume: about equal
  };
  const double off = centreOf(vtkMedialGhostPass::Off, "volume-off.png");
  const double ghost = centreOf(vtkMedialGhostPass::Ghost, "volume-ghost.png");
  const double cutaway = centreOf(vtkMedialGhostPass::Cutaway, "volume-cutaway.png");
  std::printf("red - blue at the centre: off %.0f, ghost %.0f, cutaway %.0f\n", off, ghost, cutaway);
  EXPECT_LT(off, 30.0);
  EXPECT_GT(ghost, off + 60.0);
  EXPECT_GT(cutaway, ghost + 20.0);
}

TEST(GhostView, NoInterestObjectRendersPlainlyWithoutError) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere withPass(vtkMedialGhostPass::Ghost);
  withPass.scene->SetImportance(withPass.interest, 0.0);  // back to context
  auto errors = medial::ErrorCollector::Watch(withPass.scene->GetGhostPass());
  auto image = render(withPass.scene, "no-interest.png");
  BoxAndSphere off(vtkMedialGhostPass::Off);
  auto reference = render(off.scene, "off.png");
  ASSERT_NE(image, nullptr);
  EXPECT_FALSE(errors->HasErrors()) << errors->Joined();
  EXPECT_EQ(withPass.scene->GetGhostPass()->GetLastInterestCount(), 0);
  EXPECT_TRUE(compareImages(image, reference, 8, 0.001).passed);
}

TEST(GhostView, EmptyInterestActorIsHarmless) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere scene(vtkMedialGhostPass::Ghost);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  auto empty = vtkSmartPointer<vtkActor>::New();
  empty->SetMapper(mapper);
  scene.scene->GetRenderer()->AddActor(empty);
  scene.scene->SetImportance(empty, 1.0);
  auto errors = medial::ErrorCollector::Watch(scene.scene->GetGhostPass());
  auto image = render(scene.scene, "empty-actor.png");
  ASSERT_NE(image, nullptr);
  EXPECT_FALSE(errors->HasErrors()) << errors->Joined();
  EXPECT_GT(countHues(image).red, 0.03);  // the sphere still shows
}

TEST(GhostView, ZeroSizeViewportRendersNothingWithoutError) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere scene(vtkMedialGhostPass::Ghost);
  scene.scene->GetRenderer()->SetViewport(0.5, 0.5, 0.5, 0.5);
  auto errors = medial::ErrorCollector::Watch(scene.scene->GetGhostPass());
  auto image = render(scene.scene, "zero-viewport.png");
  ASSERT_NE(image, nullptr);
  EXPECT_FALSE(errors->HasErrors()) << errors->Joined();
  EXPECT_EQ(scene.scene->GetGhostPass()->GetLastMapSize()[0], 0);
}

TEST(GhostView, ImportanceIsClampedAndZeroRemovesIt) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  EXPECT_EQ(vtkMedialGhostPass::GetImportance(actor), 0.0);
  vtkMedialGhostPass::SetImportance(actor, 3.0);
  EXPECT_EQ(vtkMedialGhostPass::GetImportance(actor), 1.0);
  vtkMedialGhostPass::SetImportance(actor, 0.4);
  EXPECT_DOUBLE_EQ(vtkMedialGhostPass::GetImportance(actor), 0.4);
  vtkMedialGhostPass::SetImportance(actor, std::nan(""));
  EXPECT_EQ(vtkMedialGhostPass::GetImportance(actor), 0.0);
  EXPECT_FALSE(actor->GetPropertyKeys()->Has(vtkMedialGhostPass::IMPORTANCE()));
  vtkMedialGhostPass::SetImportance(nullptr, 1.0);  // no crash
  EXPECT_EQ(vtkMedialGhostPass::GetImportance(nullptr), 0.0);
}

TEST(GhostView, TranslucentPropsCompositeInEveryTranslucencyMode) {
  MEDIAL_REQUIRE_DISPLAY();
  for (int translucency : {vtkMedialGhostPass::Blended, vtkMedialGhostPass::DepthPeeling,
                           vtkMedialGhostPass::OrderIndependent}) {
    // Box and sphere of interest as before, plus a translucent sphere (blue) beside the box.
    BoxAndSphere scene(vtkMedialGhostPass::Ghost);
    scene.scene->SetMeshOpacity(0.5);
    scene.scene->AddData(sphere(1.0, 3.2, 0, 0));
    scene.scene->GetGhostPass()->SetTranslucency(translucency);
    auto errors = medial::ErrorCollector::Watch(scene.scene->GetGhostPass());
    auto image = render(scene.scene, "translucency" + std::to_string(translucency) + ".png");
    ASSERT_NE(image, nullptr);
    EXPECT_FALSE(errors->HasErrors()) << errors->Joined();
    const Hues hues = countHues(image);
    EXPECT_GT(hues.red, 0.02) << "translucency " << translucency;
    EXPECT_GT(hues.blue, 0.005) << "translucency " << translucency;
  }
}

// The importance map (the paper's Figs. 2, 4, 6) read back: non-zero exactly where the object of interest
// projects, its importance there; nothing kept for a frame without objects of interest.
TEST(GhostView, ImportanceMapCoversExactlyTheObjectOfInterest) {
  MEDIAL_REQUIRE_DISPLAY();
  BoxAndSphere ghost(vtkMedialGhostPass::Ghost);
  vtkMedialGhostPass* pass = ghost.scene->GetGhostPass();
  pass->SetMapScale(1.0);
  pass->SetBorderWidth(0);
  pass->KeepImportanceMapOn();
  vtkMedialGhostPass::SetImportance(ghost.interest, 0.8);
  ASSERT_NE(render(ghost.scene, "ghost.png"), nullptr);
  const vtkSmartPointer<vtkImageData> map = pass->GetImportanceMap();  // the next frames replace it
  int dims[3];
  map->GetDimensions(dims);
  ASSERT_EQ(dims[0], 320);
  ASSERT_EQ(dims[1], 240);
  vtkDataArray* values = map->GetPointData()->GetScalars();
  ASSERT_TRUE(values && values->GetNumberOfComponents() == 3);

  // The sphere alone, same camera: its pixels are the map's.
  vtkProp3D* occluder = nullptr;
  vtkPropCollection* props = ghost.scene->GetRenderer()->GetViewProps();
  props->InitTraversal();
  for (vtkProp* prop = props->GetNextProp(); prop; prop = props->GetNextProp())
    if (prop != ghost.interest && vtkProp3D::SafeDownCast(prop)) occluder = vtkProp3D::SafeDownCast(prop);
  ASSERT_NE(occluder, nullptr);
  occluder->VisibilityOff();
  pass->SetMode(vtkMedialGhostPass::Off);
  const std::string path = scratchDir("ghost-importance-map") + "/sphere.png";
  ASSERT_TRUE(ghost.scene->RenderToImage(path.c_str(), 320, 240));
  vtkSmartPointer<vtkImageData> alone;
  alone.TakeReference(loadPng(path));
  ASSERT_NE(alone, nullptr);
  int both = 0, onlyMap = 0, onlySphere = 0;
  double importance = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      double difference = 0;
      for (int c = 0; c < 3; ++c)
        difference = std::max(difference, std::abs(alone->GetScalarComponentAsDouble(x, y, 0, c) -
                                                   alone->GetScalarComponentAsDouble(0, y, 0, c)));
      const vtkIdType i = vtkIdType(y) * 320 + x;
      const bool inMap = values->GetComponent(i, 2) > 0.5, inSphere = difference > 30;
      both += inMap && inSphere;
      onlyMap += inMap && !inSphere;
      onlySphere += !inMap && inSphere;
      if (inMap) importance = std::max(importance, values->GetComponent(i, 0));
    }
  ASSERT_GT(both, 1000);
  EXPECT_GT(double(both) / (both + onlyMap + onlySphere), 0.95)
      << onlyMap << " map-only, " << onlySphere << " sphere-only";
  EXPECT_NEAR(importance, 0.8, 1e-3);

  // A frame without an object of interest keeps no map.
  pass->SetMode(vtkMedialGhostPass::Ghost);
  vtkMedialGhostPass::SetImportance(ghost.interest, 0.0);
  ASSERT_TRUE(ghost.scene->RenderToImage(path.c_str(), 320, 240));
  EXPECT_EQ(pass->GetImportanceMap()->GetNumberOfPoints(), 0);
}
