// medial-gui's workflows driven through the UI with QTest, as a person would: open each kind of sample,
// press a panel's Run button, wait, check the object list and the picture; cancel a long run; open a
// corrupt file. Run under xvfb-run (QOpenGLWidget needs an X server).
#include "ImageComparison.h"
#include "TestPaths.h"

#include "CenterlinePanel.h"
#include "IsoSurfacePanel.h"
#include "ProfileChart.h"
#include "SampleMenu.h"
#include "TerrainView.h"
#include "MainWindow.h"
#include "ObjectList.h"
#include "SketchPanel.h"
#include "SkeletonPanel.h"
#include "SqmPanel.h"
#include "SkeletonEditor.h"
#include "StartupActions.h"
#include "VtkView.h"
#include "rig/RigExport.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialGhostPass.h"
#include "vtkMedialSQM.h"
#include "vtkMedialSketchSkeleton.h"
#include "vtkMedialTskCenterline.h"
#include "vtkMedialScene.h"

#include <chrono>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QDragEnterEvent>
#include <QDockWidget>
#include <QDropEvent>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QUrl>
#include <QMouseEvent>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QTabWidget>
#include <QTest>
#include <QTimer>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkIdList.h>
#include <vtkMapper.h>
#include <vtkMath.h>
#include <vtkRendererCollection.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace {

using namespace medial::gui;
using medial::test::dataPath;

class GuiWorkflow : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!medial::test::hasDisplay()) GTEST_SKIP() << "no X display: run the tests under xvfb-run -a";
    // One scratch folder per test (scratchDir empties the folder it returns).
    dir = medial::test::scratchDir(std::string("gui-workflow/") +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
    window = std::make_unique<MainWindow>();
    window->setErrorHandler(
        [this](const QString& title, const QString& message) { errors.append(title + ": " + message); });
    window->resize(1280, 860);
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  }

  void open(const std::string& path) {
    ASSERT_TRUE(window->openFile(QString::fromStdString(path))) << errors.join("\n").toStdString();
  }

  // Presses the panel's Run button as a user would and waits for the filter to finish.
  bool runThroughUi(FilterPanel* panel, int timeoutMs = 120000) {
    auto* run = panel->findChild<QPushButton*>("run");
    EXPECT_TRUE(run && run->isEnabled());
    if (!run || !run->isEnabled()) return false;
    QTest::mouseClick(run, Qt::LeftButton);
    EXPECT_TRUE(panel->isRunning());
    QElapsedTimer clock;
    clock.start();
    while (panel->isRunning() && clock.elapsed() < timeoutMs) QTest::qWait(20);
    QTest::qWait(20);
    return !panel->isRunning() && panel->lastRunSucceeded();
  }

  SceneObject* object(const QString& name) { return window->objects()->findByName(name); }

  // Saves the 3-D view and returns the share of its pixels that are not background.
  double screenshot(const std::string& name) {
    window->view()->update();
    QTest::qWait(50);
    const std::string png = dir + "/" + name + ".png";
    EXPECT_TRUE(window->saveScreenshot(QString::fromStdString(png)));
    return medial::test::foregroundFractionOfPng(png);
  }

  std::string dir;
  std::unique_ptr<MainWindow> window;
  QStringList errors;
};

}  // namespace

TEST_F(GuiWorkflow, OpensEveryKindOfSample) {
  open(dataPath("meshes/torus.off"));
  open(dataPath("skeletons/figure.vtp"));
  open(dataPath("skeletons/hand.swc"));
  open(dataPath("sketches/bird.txt"));
  open(dataPath("volumes/tubes/u.nii.gz"));
  ASSERT_EQ(window->objectCount(), 5);
  EXPECT_EQ(window->objects()->at(0)->kind, SceneObject::Kind::Mesh);
  EXPECT_EQ(window->objects()->at(1)->kind, SceneObject::Kind::Skeleton);
  EXPECT_EQ(window->objects()->at(2)->kind, SceneObject::Kind::Skeleton);
  EXPECT_EQ(window->objects()->at(3)->kind, SceneObject::Kind::Sketch);
  EXPECT_EQ(window->objects()->at(4)->kind, SceneObject::Kind::Volume);
  EXPECT_TRUE(window->sliceViews()->isVisible()) << "a volume shows its slice views";
  EXPECT_TRUE(window->recentFiles().first().endsWith("u.nii.gz"));
  EXPECT_GT(screenshot("every-kind"), 0.05);
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

TEST_F(GuiWorkflow, HeadCtInSlicesAndIsoSurface) {
  const std::string ct = medial::test::externalPath("invesalius/Cranium.inv3");
  MEDIAL_REQUIRE_FILE(ct);
  open(ct);
  SliceViews* slices = window->sliceViews();
  ASSERT_TRUE(slices->isVisible());
  EXPECT_DOUBLE_EQ(slices->window(), 400) << "CT opens in the soft-tissue window";
  // Bone preset, then a right-drag in the axial view widens the window.
  slices->findChild<QComboBox*>("windowLevelPreset")->setCurrentIndex(1);
  EXPECT_DOUBLE_EQ(slices->window(), 1800);
  SliceView* axial = slices->view(2);
  const QPoint centre = axial->rect().center();
  QTest::mousePress(axial, Qt::RightButton, Qt::NoModifier, centre);
  QMouseEvent move(QEvent::MouseMove, centre + QPoint(60, 0), axial->mapToGlobal(centre + QPoint(60, 0)),
                   Qt::NoButton, Qt::RightButton, Qt::NoModifier);
  QApplication::sendEvent(axial, &move);
  QTest::mouseRelease(axial, Qt::RightButton, Qt::NoModifier, centre + QPoint(60, 0));
  EXPECT_GT(slices->window(), 1800);
  // A click in the axial view moves the crosshair: the coronal and sagittal slices follow.
  const int coronalBefore = slices->view(1)->sliceIndex();
  QTest::mouseClick(axial, Qt::LeftButton, Qt::NoModifier, centre + QPoint(0, axial->height() / 4));
  EXPECT_NE(slices->view(1)->sliceIndex(), coronalBefore);
  // The wheel steps through axial slices.
  const int axialBefore = axial->sliceIndex();
  QWheelEvent wheel(centre, axial->mapToGlobal(centre), QPoint(), QPoint(0, 360), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(axial, &wheel);
  EXPECT_EQ(axial->sliceIndex(), axialBefore + 3);

  // Bone iso-surface at 300 HU, in 3-D.
  window->isoSurfacePanel()->form()->setValue("Value", 300);
  ASSERT_TRUE(runThroughUi(window->isoSurfacePanel())) << errors.join("\n").toStdString();
  SceneObject* bone = object("Cranium.inv3 iso 300");
  ASSERT_NE(bone, nullptr);
  EXPECT_GT(bone->polyData()->GetNumberOfPolys(), 10000);
  window->resetCamera();
  EXPECT_GT(screenshot("cranium-bone"), 0.1);
}

// "Key: value" pairs of PrintSelf that describe parameters: those two fresh filters print alike, less
// addresses, times and reference counts (pipeline details, which differ between objects). Returns the pairs
// of `filter` that differ from the fresh filters'.
std::set<std::string> differingParameters(vtkAlgorithm* filter, vtkAlgorithm* freshA, vtkAlgorithm* freshB) {
  auto pairs = [](vtkAlgorithm* f) {
    std::ostringstream text;
    f->PrintSelf(text, vtkIndent());
    std::map<std::string, std::string> values;
    std::istringstream in(text.str());
    for (std::string line; std::getline(in, line);) {
      const size_t colon = line.find(": "), first = line.find_first_not_of(' ');
      if (colon != std::string::npos && first < colon)
        values.emplace(line.substr(first, colon - first), line.substr(colon + 2));
    }
    return values;
  };
  const auto a = pairs(freshA), b = pairs(freshB), mine = pairs(filter);
  std::set<std::string> differing;
  for (const auto& [key, value] : a) {
    const auto other = b.find(key), own = mine.find(key);
    const bool parameter = other != b.end() && other->second == value &&
                           key.find("Time") == std::string::npos && key != "Reference Count" &&
                           value.find("0x") == std::string::npos;
    if (parameter && own != mine.end() && own->second != value && own->second.find("0x") == std::string::npos)
      differing.insert(key + ": " + own->second);
  }
  return differing;
}

// Each panel's form, untouched, configures its filter exactly as a fresh filter (the Python and command
// line default) but for the GUI's documented presets.
TEST_F(GuiWorkflow, FormDefaultsAreTheFiltersDefaults) {
  open(dataPath("meshes/torus.off"));
  open(dataPath("skeletons/figure.vtp"));
  open(dataPath("sketches/bird.txt"));
  open(dataPath("volumes/tubes/u.nii.gz"));
  struct Case {
    FilterPanel* panel;
    SceneObject* input;
    vtkSmartPointer<vtkAlgorithm> freshA, freshB;
    std::set<std::string> presets;  // the lines the GUI sets on purpose
  };
  const std::vector<Case> cases = {
      {window->skeletonPanel(),
       window->objects()->at(0),
       vtkSmartPointer<vtkMedialContractionSkeleton>::New(),
       vtkSmartPointer<vtkMedialContractionSkeleton>::New(),
       {"ComputeWeights: 1"}},
      {window->sqmPanel(),
       window->objects()->at(1),
       vtkSmartPointer<vtkMedialSQM>::New(),
       vtkSmartPointer<vtkMedialSQM>::New(),
       {"CountOverlaps: 1"}},
      {window->sketchPanel(),
       window->objects()->at(2),
       vtkSmartPointer<vtkMedialSketchSkeleton>::New(),
       vtkSmartPointer<vtkMedialSketchSkeleton>::New(),
       {}},
      {window->centerlinePanel(),
       window->objects()->at(3),
       vtkSmartPointer<vtkMedialTskCenterline>::New(),
       vtkSmartPointer<vtkMedialTskCenterline>::New(),
       {"ComputeSections: 1", "ComputeSurface: 1"}},
  };
  for (const Case& c : cases) {
    const vtkSmartPointer<vtkAlgorithm> configured = c.panel->configuredFilter(c.input);
    ASSERT_TRUE(configured) << c.panel->title().toStdString();
    EXPECT_EQ(differingParameters(configured, c.freshA, c.freshB), c.presets)
        << c.panel->title().toStdString();
  }
}

TEST_F(GuiWorkflow, SkeletonGhostViewSqmAndRig) {
  open(dataPath("meshes/torus.off"));
  ASSERT_TRUE(runThroughUi(window->skeletonPanel())) << errors.join("\n").toStdString();
  SceneObject* skeleton = object("torus.off skeleton");
  SceneObject* segments = object("torus.off segments");
  ASSERT_NE(skeleton, nullptr);
  ASSERT_NE(segments, nullptr);
  EXPECT_GE(skeleton->polyData()->GetNumberOfPoints(), 4);
  EXPECT_TRUE(skeleton->interest) << "the skeleton is shown through its mesh";
  ASSERT_TRUE(skeleton->skinnedMesh);
  EXPECT_TRUE(segments->polyData()->GetPointData()->GetArray("SkeletonNode"));
  EXPECT_TRUE(window->logText().contains("Skeleton: done in"));

  // Colour by bone 0's weight; ghost view and cutaway both draw something.
  EXPECT_TRUE(window->skeletonPanel()->selectBone(skeleton, 0));
  EXPECT_TRUE(window->legendShown()) << "a colour scale for the weights";
  window->setGhostMode(vtkMedialGhostPass::Ghost);
  EXPECT_GT(screenshot("torus-ghost"), 0.05);
  EXPECT_EQ(window->scene()->GetGhostPass()->GetLastInterestCount(), 1);
  auto* layers = window->findChild<QAction*>("ghostLayers");
  ASSERT_NE(layers, nullptr);
  layers->setChecked(true);
  EXPECT_TRUE(window->scene()->GetGhostPass()->GetLayeredGhosts());
  EXPECT_GT(screenshot("torus-ghost-layers"), 0.05);
  layers->setChecked(false);
  window->setGhostMode(vtkMedialGhostPass::Cutaway);
  EXPECT_GT(screenshot("torus-cutaway"), 0.05);

  // Rig export (GLB) and Save As of the skeleton (SWC).
  ASSERT_TRUE(window->objects()->exportRig(skeleton, QString::fromStdString(dir + "/torus-rig.glb")));
  EXPECT_GT(std::filesystem::file_size(dir + "/torus-rig.glb"), 1000u);
  EXPECT_TRUE(window->logText().contains("Exported rig")) << window->logText().toStdString();
  // Export Rig's choices: root node, up axis, scale (as --root, --up-axis, --scale), and the log says so.
  medial::gui::RigExportSettings settings;
  settings.root = 1;
  settings.upAxis = "z";
  settings.scale = 0.5;
  ASSERT_TRUE(
      window->objects()->exportRig(skeleton, QString::fromStdString(dir + "/torus-rig-z.glb"), settings));
  EXPECT_TRUE(window->logText().contains("Root at node 1, up axis z, scale 0.5"))
      << window->logText().toStdString();
  settings.root = 100000;
  EXPECT_FALSE(window->objects()->exportRig(skeleton, QString::fromStdString(dir + "/bad.glb"), settings));
  EXPECT_FALSE(std::filesystem::exists(dir + "/bad.glb"));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.front().contains("node 100000 is not a node")) << errors.front().toStdString();
  errors.clear();
  // The rig opens again: the torus's mesh, and its skeleton as a second object (FBX as well).
  ASSERT_TRUE(window->objects()->exportRig(skeleton, QString::fromStdString(dir + "/torus-rig.fbx")));
  for (const char* rig : {"/torus-rig.glb", "/torus-rig.fbx"}) {
    const int before = window->objectCount();
    open(dir + rig);
    ASSERT_EQ(window->objectCount(), before + 2) << rig;
    EXPECT_EQ(window->objects()->at(before)->kind, SceneObject::Kind::Mesh);
    EXPECT_GT(window->objects()->at(before)->polyData()->GetNumberOfPolys(), 1000);
    SceneObject* bones = window->objects()->at(before + 1);
    EXPECT_EQ(bones->kind, SceneObject::Kind::Skeleton) << rig;
    EXPECT_GE(bones->polyData()->GetNumberOfLines(), skeleton->polyData()->GetNumberOfLines()) << rig;
    window->objects()->remove(bones);
    window->objects()->remove(window->objects()->at(before));
  }
  ASSERT_TRUE(window->objects()->save(skeleton, QString::fromStdString(dir + "/torus-skeleton.vtp")));
  // SWC holds trees only: the torus's cycle is refused with a message.
  EXPECT_FALSE(window->objects()->save(skeleton, QString::fromStdString(dir + "/torus-skeleton.swc")));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.first().contains("torus-skeleton.swc")) << errors.first().toStdString();
  errors.clear();

  // SQM of the computed skeleton; the subdivision slider updates the mesh live.
  window->sqmPanel()->setInput(skeleton);
  ASSERT_TRUE(runThroughUi(window->sqmPanel())) << errors.join("\n").toStdString();
  SceneObject* sqm = object("torus.off skeleton SQM");
  ASSERT_NE(sqm, nullptr);
  // One tessellation level turns every n-gon into n quads.
  const vtkIdType corners = sqm->polyData()->GetPolys()->GetNumberOfConnectivityIds();
  window->sqmPanel()->subdivisionSlider()->setValue(1);
  ASSERT_TRUE(window->sqmPanel()->isRunning()) << "the slider re-runs the filter";
  window->sqmPanel()->wait();
  sqm = object("torus.off skeleton SQM");
  ASSERT_NE(sqm, nullptr);
  EXPECT_EQ(sqm->polyData()->GetNumberOfPolys(), corners) << "one tessellation level: one quad per corner";
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

// Overlapping tubes: the log counts them and points at the Union box; ticked, the mesh is re-made live as
// the union (more faces: the cut polygons' triangles) and the log says so.
TEST_F(GuiWorkflow, SqmUnitesOverlappingTubes) {
  open(dataPath("skeletons/overlapping/crossing.vtp"));
  SqmPanel* sqm = window->sqmPanel();
  sqm->setInput(object("crossing.vtp"));
  ASSERT_TRUE(runThroughUi(sqm)) << errors.join("\n").toStdString();
  EXPECT_TRUE(window->logText().contains("tubes overlap at 6 pairs of nodes"))
      << window->logText().toStdString();
  EXPECT_TRUE(window->logText().contains("Union of overlapping tubes"));
  const vtkIdType before = object("crossing.vtp SQM")->polyData()->GetNumberOfPolys();
  sqm->form()->setValue("Union", 1);
  ASSERT_TRUE(sqm->isRunning()) << "the box re-runs the filter";
  sqm->wait();
  SceneObject* united = object("crossing.vtp SQM");
  ASSERT_NE(united, nullptr);
  EXPECT_GT(united->polyData()->GetNumberOfPolys(), before);
  EXPECT_TRUE(window->logText().contains("united (22 polygons cut)")) << window->logText().toStdString();
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

TEST_F(GuiWorkflow, CenterlineFromClickedSeedAndFlyThrough) {
  open(dataPath("volumes/tubes/u.nii.gz"));
  CenterlinePanel* panel = window->centerlinePanel();
  window->filterTabs()->setCurrentIndex(2);
  panel->form()->setValue("Selection", 0);  // label 1
  // Seed: a click in the axial slice view (the centerline tab is showing).
  SliceView* axial = window->sliceViews()->view(2);
  QTest::mouseClick(axial, Qt::LeftButton, Qt::NoModifier, axial->rect().center());
  ASSERT_TRUE(panel->seed().has_value());
  panel->clearSeed();  // the centre of the U is outside the tube: let P0 be the lowest end
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  // The tube's wall, to fly inside.
  window->isoSurfacePanel()->form()->setValue("Value", 0.5);
  ASSERT_TRUE(runThroughUi(window->isoSurfacePanel())) << errors.join("\n").toStdString();
  SceneObject* line = object("u.nii.gz centerline");
  ASSERT_NE(line, nullptr);
  EXPECT_GT(line->polyData()->GetNumberOfPoints(), 20);
  // Sections every 1 mm along the ~99 mm axis, and the unfolded wall (sections x 72 angles).
  EXPECT_GT(panel->profilePoints(), 80);
  EXPECT_GT(panel->terrainImage().width(), 80);
  EXPECT_EQ(panel->terrainImage().height(), 72);

  // Fly-through: the slider puts the camera on the centerline, looking along it.
  const FlyThrough& fly = panel->flyThrough();
  ASSERT_FALSE(fly.empty());
  panel->setPosition(0.5 * fly.length());
  vtkCamera* camera = window->scene()->GetRenderer()->GetActiveCamera();
  const auto eye = fly.eye(0.5 * fly.length());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(camera->GetPosition()[i], eye[i], 1e-6);
  EXPECT_DOUBLE_EQ(camera->GetViewAngle(), 80.0);
  EXPECT_GT(screenshot("u-inside"), 0.1) << "inside the tube the wall fills the view";
  // Play moves forward; pause stops.
  panel->play(true);
  QTest::qWait(300);
  panel->play(false);
  EXPECT_GT(panel->position(), 0.5 * fly.length());
}

// The virtual-colonoscopy tools as a user meets them: a run leaves the camera alone; a click on the unfolded
// wall or the profile flies there; the profile reads out the section under the mouse and exports CSV and
// PNG; the fly-through goes backward (looking back) and takes another field of view.
TEST_F(GuiWorkflow, VirtualColonoscopyToolsMoveTheFlyThrough) {
  open(dataPath("volumes/tubes/u.nii.gz"));
  CenterlinePanel* panel = window->centerlinePanel();
  window->filterTabs()->setCurrentIndex(2);
  panel->form()->setValue("Selection", 0);  // label 1
  vtkCamera* camera = window->scene()->GetRenderer()->GetActiveCamera();
  camera->SetPosition(11, 222, 333);
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  EXPECT_DOUBLE_EQ(camera->GetPosition()[1], 222) << "a run leaves the camera where the user left it";
  const FlyThrough& fly = panel->flyThrough();
  ASSERT_GT(fly.length(), 80);

  // A click on the wall, 60 % along it.
  TerrainView* wall = panel->terrain();
  const double target = 0.6 * fly.length();
  QTest::mouseClick(wall, Qt::LeftButton, Qt::NoModifier, QPoint(wall->xAt(target), 40));
  EXPECT_NEAR(panel->position(), target, fly.length() / wall->width() + 1.0) << "the click flies there";
  const auto eye = fly.eye(panel->position());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(camera->GetPosition()[i], eye[i], 1e-6);

  // The profile: a readout under the mouse, a click that flies, the exports.
  ProfileChart* profile = panel->profile();
  QChartView* chart = profile->view();
  const QPointF at30 = chart->chart()->mapToPosition(QPointF(30, 5), chart->chart()->series().first());
  const QPoint viewport = chart->mapFromScene(chart->chart()->mapToScene(at30));
  QMouseEvent move(QEvent::MouseMove, QPointF(viewport), chart->viewport()->mapToGlobal(QPointF(viewport)),
                   Qt::NoButton, Qt::NoButton, Qt::NoModifier);
  QApplication::sendEvent(chart->viewport(), &move);
  EXPECT_TRUE(profile->readout().startsWith("arc 3")) << profile->readout().toStdString();
  EXPECT_TRUE(profile->readout().contains("min")) << profile->readout().toStdString();
  QTest::mouseClick(chart->viewport(), Qt::LeftButton, Qt::NoModifier, viewport);
  EXPECT_NEAR(panel->position(), 30, 2.0);
  QString error;
  ASSERT_TRUE(profile->exportCsv(QString::fromStdString(dir + "/profile.csv"), error)) << error.toStdString();
  std::ifstream csv(dir + "/profile.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "arc_length_mm,min_diameter_mm,max_diameter_mm,perimeter_mm,area_mm2,bridged");
  ASSERT_TRUE(profile->exportPng(QString::fromStdString(dir + "/profile.png")));
  EXPECT_GT(QImage(QString::fromStdString(dir + "/profile.png")).width(), 100);

  // The centerline saved for 3D Slicer.
  SceneObject* line = object("u.nii.gz centerline");
  ASSERT_NE(line, nullptr);
  ASSERT_TRUE(window->objects()->save(line, QString::fromStdString(dir + "/u.mrk.json")));
  std::ifstream markups(dir + "/u.mrk.json");
  const std::string json((std::istreambuf_iterator<char>(markups)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"type\": \"Curve\""), std::string::npos);
  EXPECT_NE(json.find("\"Radius\""), std::string::npos);

  // Backward: looking towards the start; playing goes back; the view angle follows its box.
  panel->setBackward(true);
  panel->setPosition(50);
  const auto ahead = fly.eye(52), here = fly.eye(50);
  double forward = 0;
  for (int i = 0; i < 3; ++i) forward += (camera->GetFocalPoint()[i] - here[i]) * (ahead[i] - here[i]);
  EXPECT_LT(forward, 0) << "backward looks back along the line";
  panel->play(true);
  QTest::qWait(300);
  panel->play(false);
  EXPECT_LT(panel->position(), 50);
  panel->setViewAngle(110);
  EXPECT_DOUBLE_EQ(camera->GetViewAngle(), 110.0);

  // The slice views name the patient's directions at their edges (left, right, top, bottom; LPS data).
  EXPECT_EQ(window->sliceViews()->view(2)->orientationLetters(), "R L A P") << "axial, from the feet";
  EXPECT_EQ(window->sliceViews()->view(1)->orientationLetters(), "R L S I") << "coronal, from the front";
  EXPECT_EQ(window->sliceViews()->view(0)->orientationLetters(), "A P S I") << "sagittal, from the left";
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

TEST_F(GuiWorkflow, SketchFileAndDrawnStrokes) {
  open(dataPath("sketches/hand.txt"));
  SketchPanel* panel = window->sketchPanel();
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  SceneObject* skeleton = object("hand.txt skeleton");
  ASSERT_NE(skeleton, nullptr);
  ASSERT_NE(object("hand.txt mesh"), nullptr);
  const vtkIdType fine = skeleton->polyData()->GetNumberOfPoints();
  // A much larger pruning threshold removes branches, live.
  panel->thresholdSlider(2)->setValue(300);
  panel->wait();
  skeleton = object("hand.txt skeleton");
  ASSERT_NE(skeleton, nullptr);
  EXPECT_LT(skeleton->polyData()->GetNumberOfPoints(), fine);

  // Drawing: a left drag in the 3-D view draws a closed stroke on the view plane; skeleton and mesh appear.
  panel->setDrawing(true);
  VtkView* view = window->view();
  const QPoint centre = view->rect().center();
  auto drawEllipse = [&](int rx, int ry) {
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(rx, 0));
    for (int step = 1; step < 48; ++step) {
      const double angle = 2 * M_PI * step / 48;
      const QPoint at =
          centre + QPoint(static_cast<int>(rx * std::cos(angle)), static_cast<int>(ry * std::sin(angle)));
      QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                       Qt::NoModifier);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(rx, -5));
  };
  drawEllipse(150, 60);
  ASSERT_NE(object("drawn sketch"), nullptr);
  panel->wait();
  SceneObject* drawn = object("drawn sketch skeleton");
  ASSERT_NE(drawn, nullptr) << errors.join("\n").toStdString();
  EXPECT_GE(drawn->polyData()->GetNumberOfPoints(), 2);
  // Turn the view by 90 degrees and draw a second part: it lies in the new view plane, across the first.
  window->scene()->GetRenderer()->GetActiveCamera()->Azimuth(90);
  window->scene()->GetRenderer()->ResetCameraClippingRange();
  drawEllipse(40, 120);
  panel->wait();
  vtkPolyData* strokes = object("drawn sketch")->polyData();
  ASSERT_EQ(strokes->GetNumberOfLines(), 2);
  vtkDataArray* placement = strokes->GetCellData()->GetArray("Placement");
  ASSERT_NE(placement, nullptr);
  double first[16], second[16];
  placement->GetTuple(0, first);
  placement->GetTuple(1, second);
  // The planes' normals (third columns) are perpendicular.
  EXPECT_NEAR(first[2] * second[2] + first[6] * second[6] + first[10] * second[10], 0.0, 1e-6);
  drawn = object("drawn sketch skeleton");
  ASSERT_NE(drawn, nullptr) << errors.join("\n").toStdString();
  vtkDataArray* part = drawn->polyData()->GetPointData()->GetArray("Part");
  ASSERT_NE(part, nullptr);
  EXPECT_EQ(part->GetRange()[1], 1.0) << "two parts";
  panel->setDrawing(false);
  EXPECT_GT(screenshot("drawn-sketch"), 0.02);
}

TEST_F(GuiWorkflow, CancelALongRunAndRecover) {
  // A dense sphere (~40,000 vertices) keeps the contraction busy for seconds.
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetThetaResolution(200);
  sphere->SetPhiResolution(200);
  sphere->Update();
  const std::string path = dir + "/dense-sphere.vtp";
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(sphere->GetOutput());
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
  open(path);

  SkeletonPanel* panel = window->skeletonPanel();
  QTest::mouseClick(panel->findChild<QPushButton*>("run"), Qt::LeftButton);
  ASSERT_TRUE(panel->isRunning());
  QTest::qWait(200);
  QElapsedTimer clock;
  clock.start();
  QTest::mouseClick(panel->findChild<QPushButton*>("cancel"), Qt::LeftButton);
  panel->wait();
  EXPECT_LT(clock.elapsed(), 15000) << "cancel took too long";
  EXPECT_FALSE(panel->lastRunSucceeded());
  EXPECT_TRUE(window->logText().contains("Skeleton: cancelled"));
  EXPECT_TRUE(errors.isEmpty()) << "a cancel is not an error: " << errors.join("\n").toStdString();
  EXPECT_EQ(window->objectCount(), 1);
  // The window still works: the Run button is back and a small mesh runs to the end.
  EXPECT_TRUE(panel->findChild<QPushButton*>("run")->isEnabled());
  open(dataPath("meshes/capsule.vtp"));
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  EXPECT_NE(object("capsule.vtp skeleton"), nullptr);
}

TEST_F(GuiWorkflow, CorruptFilesGiveAnErrorAndTheSessionGoesOn) {
  std::ofstream(dir + "/truncated.off") << "OFF\n10000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::ofstream(dir + "/claims-4gb.mha") << "ObjectType = Image\nNDims = 3\nElementType = MET_UCHAR\n"
                                         << "DimSize = 2000 2000 1000\nElementDataFile = LOCAL\nxxxx";
  for (const char* name :
       {"corrupt.vtp", "corrupt.nii.gz", "corrupt.txt", "truncated.off", "claims-4gb.mha"}) {
    if (!std::filesystem::exists(dir + "/" + name))
      std::ofstream(dir + "/" + name) << "this is not a " << name << " file\n";
    errors.clear();
    EXPECT_FALSE(window->openFile(QString::fromStdString(dir + "/" + name)));
    ASSERT_EQ(errors.size(), 1) << name;
    EXPECT_TRUE(errors.first().contains(name)) << errors.first().toStdString();
  }
  EXPECT_EQ(window->objectCount(), 0);
  errors.clear();
  open(dataPath("meshes/capsule.vtp"));
  EXPECT_GT(screenshot("after-corrupt"), 0.03);
  // A filter without input says so instead of running.
  EXPECT_FALSE(window->centerlinePanel()->run());
  EXPECT_EQ(errors.size(), 1);
}

TEST_F(GuiWorkflow, DeletingAnObjectUpdatesListAndPanels) {
  open(dataPath("skeletons/figure.vtp"));
  open(dataPath("volumes/tubes/u.nii.gz"));
  EXPECT_NE(window->sqmPanel()->input(), nullptr);
  window->objects()->remove(window->objects()->at(1));
  EXPECT_FALSE(window->sliceViews()->isVisible()) << "no volume left";
  window->objects()->remove(window->objects()->at(0));
  EXPECT_EQ(window->sqmPanel()->input(), nullptr);
  EXPECT_FALSE(window->sqmPanel()->run());
}

TEST_F(GuiWorkflow, ColonPhantomDicomThresholdSeedCenterlineFlyThrough) {
  // The CT-like colon phantom, written as a DICOM series by its generator, opened as a folder.
  const std::string series = dir + "/colon-dicom";
  ASSERT_TRUE(medial::test::makeColonPhantom(series));
  open(series);
  SceneObject* ct = window->objects()->at(0);
  ASSERT_EQ(ct->kind, SceneObject::Kind::Volume);
  EXPECT_DOUBLE_EQ(window->sliceViews()->window(), 400) << "a CT opens in the soft-tissue window";

  // The true axis (x y z radius per line) and the rectum's end, where the seed goes.
  std::vector<std::array<double, 3>> axis;
  std::ifstream axisFile(series + "/axis.txt");
  std::string line;
  while (std::getline(axisFile, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream values(line);
    std::array<double, 3> p;
    values >> p[0] >> p[1] >> p[2];
    axis.push_back(p);
  }
  ASSERT_GT(axis.size(), 100u);

  // Threshold: colon air, border air dropped (the panel's threshold defaults: -1024..-600 HU).
  CenterlinePanel* panel = window->centerlinePanel();
  window->filterTabs()->setCurrentIndex(2);
  panel->form()->setValue("Selection", 1);
  // Seed: a click in the axial view on the rectum (the crosshair first moved to its slice).
  const std::array<double, 3> rectum = axis[20];
  window->sliceViews()->setCursor(rectum);
  SliceView* axial = window->sliceViews()->view(2);
  axial->update();
  QTest::qWait(50);
  double display[3];
  vtkRenderer* renderer = axial->renderWindow()->GetRenderers()->GetFirstRenderer();
  renderer->SetWorldPoint(rectum[0], rectum[1], rectum[2], 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  const qreal ratio = axial->devicePixelRatioF();
  QTest::mouseClick(
      axial, Qt::LeftButton, Qt::NoModifier,
      QPoint(static_cast<int>(display[0] / ratio), static_cast<int>(axial->height() - display[1] / ratio)));
  ASSERT_TRUE(panel->seed().has_value());
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR((*panel->seed())[i], rectum[i], 2.0) << "the click lands on the rectum";

  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  SceneObject* centerline = object(ct->name + " centerline");
  ASSERT_NE(centerline, nullptr);
  // Every centerline point lies near the true axis (voxels are 0.9 x 0.9 x 1.25 mm).
  vtkPolyData* computed = centerline->polyData();
  double sum = 0;
  for (vtkIdType i = 0; i < computed->GetNumberOfPoints(); ++i) {
    double p[3], best = 1e300;
    computed->GetPoint(i, p);
    for (const auto& a : axis) best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(p, a.data())));
    sum += best;
  }
  EXPECT_LT(sum / computed->GetNumberOfPoints(), 1.5) << "mean distance to the true axis (mm)";
  EXPECT_GT(panel->flyThrough().length(), 300.0) << "the centerline runs most of the colon's 422 mm";

  // The iso-surface panel offers the colon's wall for this CT without bone (-500 HU, as docs/gui.md says).
  EXPECT_DOUBLE_EQ(window->isoSurfacePanel()->form()->value("Value"), -500.0);
  // The lumen's surface comes with the centerline (the GUI's default), and the fly-through is inside it.
  SceneObject* lumen = object(ct->name + " lumen");
  ASSERT_NE(lumen, nullptr) << "the lumen surface, made by default";
  EXPECT_GT(lumen->polyData()->GetNumberOfPolys(), 10000);
  EXPECT_LE(lumen->polyData()->GetNumberOfPolys(), 100000);
  EXPECT_TRUE(window->logText().contains("lumen surface of")) << window->logText().toStdString();
  panel->setPosition(0.3 * panel->flyThrough().length());
  // Dark, distant wall counts as background for this measure; measured 0.22 when the view is right.
  EXPECT_GT(screenshot("colon-inside"), 0.1) << "inside the colon its wall fills the view";
  EXPECT_FALSE(panel->terrainImage().isNull());
  window->grab().save(QString::fromStdString(dir + "/colon-window.png"));  // the whole window, to look at
  panel->grab().save(QString::fromStdString(dir + "/colon-panel.png"));    // the profile and the wall
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

// A colon with two collapsed segments: one centerline through the GUI, its bridges orange in the 3-D view,
// marked on the profile and as orange rows of the unfolded wall, and the note in the log.
TEST_F(GuiWorkflow, CollapsedColonIsBridgedAndTheBridgesShow) {
  const std::string volume = dir + "/collapsed.mha";
  ASSERT_TRUE(
      medial::test::makeColonPhantom(dir + "/collapsed " + volume + " --collapse 2 --gap 12 --no-dicom"));
  open(volume);
  CenterlinePanel* panel = window->centerlinePanel();
  window->filterTabs()->setCurrentIndex(2);
  panel->form()->setValue("Selection", 1);
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  SceneObject* line = object("collapsed.mha centerline");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->polyData()->GetNumberOfCells(), 1);
  EXPECT_GT(panel->flyThrough().length(), 380.0) << "the colon's 422 mm, less the ends, in one line";
  EXPECT_GT(panel->bridgedProfilePoints(), 10) << "two gaps of 12 mm, a section every 2 mm";
  EXPECT_TRUE(window->logText().contains("3 parts of the structure joined across 2 gap(s)"))
      << window->logText().toStdString();

  auto* actor = vtkActor::SafeDownCast(line->prop);
  ASSERT_NE(actor, nullptr);
  EXPECT_TRUE(actor->GetMapper()->GetScalarVisibility());
  EXPECT_STREQ(actor->GetMapper()->GetArrayName(), "Bridged");

  const QImage& terrain = panel->terrainImage();
  ASSERT_FALSE(terrain.isNull());
  int orangeColumns = 0;  // sections run across the picture
  for (int x = 0; x < terrain.width(); ++x) orangeColumns += terrain.pixel(x, 0) == qRgb(255, 140, 0);
  EXPECT_GT(orangeColumns, 10);
  window->resetCamera();
  EXPECT_GT(screenshot("collapsed-colon"), 0.05);
  window->grab().save(QString::fromStdString(dir + "/collapsed-window.png"));  // to look at
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

TEST_F(GuiWorkflow, ClicksInThe3dViewPickBonesAndObjectsOfInterest) {
  open(dataPath("meshes/capsule.vtp"));
  ASSERT_TRUE(runThroughUi(window->skeletonPanel())) << errors.join("\n").toStdString();
  SceneObject* skeleton = object("capsule.vtp skeleton");
  SceneObject* segments = object("capsule.vtp segments");
  ASSERT_NE(skeleton, nullptr);
  ASSERT_NE(segments, nullptr);
  window->resetCamera();
  QTest::qWait(50);
  // Click on the skeleton's first bone (inside the translucent mesh): the mesh shows its weights.
  vtkPolyData* bones = skeleton->polyData();
  vtkIdType count;
  const vtkIdType* ids;
  bones->GetLines()->InitTraversal();
  ASSERT_TRUE(bones->GetLines()->GetNextCell(count, ids));
  double a[3], b[3], middle[3], display[3];
  bones->GetPoint(ids[0], a);
  bones->GetPoint(ids[1], b);
  for (int i = 0; i < 3; ++i) middle[i] = 0.5 * (a[i] + b[i]);
  vtkRenderer* renderer = window->scene()->GetRenderer();
  renderer->SetWorldPoint(middle[0], middle[1], middle[2], 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  VtkView* view = window->view();
  const qreal ratio = view->devicePixelRatioF();
  const QPoint at(static_cast<int>(display[0] / ratio),
                  static_cast<int>(view->height() - display[1] / ratio));
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
  EXPECT_EQ(window->objects()->current(), skeleton) << "the click picks the skeleton inside the mesh";
  EXPECT_TRUE(window->logText().contains("Mesh colored by the weight of bone 0"))
      << window->logText().toStdString();
  // Shift+click toggles the object of interest.
  ASSERT_TRUE(skeleton->interest);
  QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, at);
  EXPECT_FALSE(skeleton->interest);
  QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, at);
  EXPECT_TRUE(skeleton->interest);
}

TEST_F(GuiWorkflow, VolumeRenderingOfTheShownVolume) {
  EXPECT_FALSE(window->setVolumeRendering(0)) << "no volume yet";
  open(dataPath("volumes/tubes/u.nii.gz"));
  ASSERT_TRUE(window->setVolumeRendering(2));  // full range: a label volume
  EXPECT_TRUE(window->hasVolumeRendering());
  EXPECT_FALSE(window->objects()->at(0)->prop->GetVisibility()) << "the slices make way";
  window->resetCamera();
  EXPECT_GT(screenshot("u-volume-rendering"), 0.03);
  // Deleting the volume removes its rendering.
  window->objects()->remove(window->objects()->at(0));
  EXPECT_FALSE(window->hasVolumeRendering());
  const std::string ct = medial::test::externalPath("invesalius/Cranium.inv3");
  if (!std::filesystem::exists(ct)) return;
  open(ct);
  ASSERT_TRUE(window->setVolumeRendering(0));  // CT bone
  window->resetCamera();
  EXPECT_GT(screenshot("cranium-volume-rendering"), 0.05);
  window->grab().save(QString::fromStdString(dir + "/cranium-window.png"));
}

TEST_F(GuiWorkflow, SketchThresholdsPerPart) {
  open(dataPath("sketches/bird.txt"));  // body, then two wings
  SketchPanel* panel = window->sketchPanel();
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  auto nodesPerPart = [this] {
    std::map<int, int> count;
    vtkDataArray* part = object("bird.txt skeleton")->polyData()->GetPointData()->GetArray("Part");
    for (vtkIdType i = 0; i < part->GetNumberOfTuples(); ++i) ++count[int(part->GetComponent(i, 0))];
    return count;
  };
  const auto before = nodesPerPart();
  ASSERT_EQ(before.size(), 3u);
  // Collapse edges hard in the first wing only (part 1): the body and the other wing keep their nodes.
  panel->setThresholdScope(1);
  panel->thresholdSlider(3)->setValue(100);
  panel->wait();
  const auto after = nodesPerPart();
  EXPECT_LT(after.at(1), before.at(1));
  EXPECT_EQ(after.at(2), before.at(2));
  // Back to the global scope: the sliders show the global values again.
  panel->setThresholdScope(-1);
  EXPECT_EQ(panel->thresholdSlider(3)->value(), 10);

  // Branch level: the body's longest branch simplified hard; only epsilon_s applies there.
  vtkPolyData* skeleton = object("bird.txt skeleton")->polyData();
  vtkDataArray* part = skeleton->GetCellData()->GetArray("Part");
  vtkDataArray* branch = skeleton->GetCellData()->GetArray("Branch");
  ASSERT_TRUE(part && branch);
  std::map<int, int> bonesOfBranch;
  for (vtkIdType c = 0; c < skeleton->GetNumberOfCells(); ++c)
    if (part->GetComponent(c, 0) == 0 && branch->GetComponent(c, 0) >= 0)
      ++bonesOfBranch[int(branch->GetComponent(c, 0))];
  ASSERT_FALSE(bonesOfBranch.empty());
  const auto longest = std::max_element(bonesOfBranch.begin(), bonesOfBranch.end(),
                                        [](const auto& a, const auto& b) { return a.second < b.second; });
  ASSERT_GT(longest->second, 1) << "the body needs a branch with several bones";
  const auto beforeBranch = nodesPerPart();
  panel->selectBranch(0, longest->first);
  EXPECT_FALSE(panel->thresholdSlider(1)->isEnabled()) << "a branch has epsilon_s only";
  panel->thresholdSlider(0)->setValue(50);
  panel->wait();
  const auto afterBranch = nodesPerPart();
  EXPECT_LT(afterBranch.at(0), beforeBranch.at(0));
  EXPECT_EQ(afterBranch.at(2), beforeBranch.at(2));

  // The same from the 3-D view: a click on a bone of the body picks its branch.
  window->resetCamera();
  QTest::qWait(50);
  skeleton = object("bird.txt skeleton")->polyData();
  part = skeleton->GetCellData()->GetArray("Part");
  branch = skeleton->GetCellData()->GetArray("Branch");
  vtkIdType bone = -1;
  for (vtkIdType c = 0; c < skeleton->GetNumberOfCells() && bone < 0; ++c)
    if (part->GetComponent(c, 0) == 0 && branch->GetComponent(c, 0) >= 0) bone = c;
  ASSERT_GE(bone, 0);
  auto ids = vtkSmartPointer<vtkIdList>::New();
  skeleton->GetCellPoints(bone, ids);
  double a[3], b[3], display[3];
  skeleton->GetPoint(ids->GetId(0), a);
  skeleton->GetPoint(ids->GetId(1), b);
  vtkRenderer* renderer = window->scene()->GetRenderer();
  renderer->SetWorldPoint(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]), 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  VtkView* view = window->view();
  const qreal ratio = view->devicePixelRatioF();
  QTest::mouseClick(
      view, Qt::LeftButton, Qt::NoModifier,
      QPoint(static_cast<int>(display[0] / ratio), static_cast<int>(view->height() - display[1] / ratio)));
  EXPECT_TRUE(window->logText().contains("Sketch: ε_s of part 1, branch")) << window->logText().toStdString();
}

// The sketch's mesh is one watertight piece; its skeleton binds to it and exports as a rig in one step.
TEST_F(GuiWorkflow, SketchBecomesARiggedCharacter) {
  open(dataPath("sketches/bird.txt"));
  ASSERT_TRUE(runThroughUi(window->sketchPanel())) << errors.join("\n").toStdString();
  SceneObject* skeleton = object("bird.txt skeleton");
  SceneObject* mesh = object("bird.txt mesh");
  ASSERT_TRUE(skeleton && mesh);
  auto regions = vtkSmartPointer<vtkPolyDataConnectivityFilter>::New();
  regions->SetInputData(mesh->polyData());
  regions->SetExtractionModeToAllRegions();
  regions->Update();
  EXPECT_EQ(regions->GetNumberOfExtractedRegions(), 1) << "body and wings joined";
  EXPECT_FALSE(skeleton->skinnedMesh);
  ASSERT_TRUE(window->objects()->bindMesh(skeleton, mesh)) << errors.join("\n").toStdString();
  ASSERT_TRUE(skeleton->skinnedMesh);
  EXPECT_TRUE(skeleton->polyData()->GetFieldData()->GetArray("Root"));
  const QString rig = QString::fromStdString(dir + "/bird.fbx");
  ASSERT_TRUE(window->objects()->exportRig(skeleton, rig)) << errors.join("\n").toStdString();
  const medial::RigSummary summary = medial::readRigSummary(rig.toStdString());
  ASSERT_TRUE(summary.error.empty()) << summary.error;
  EXPECT_EQ(summary.unweightedVertices, 0);
  EXPECT_EQ(summary.faces, mesh->polyData()->GetNumberOfPolys());
  // A skeleton cannot bind to itself: a dialog says why.
  EXPECT_FALSE(window->objects()->bindMesh(skeleton, skeleton));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.first().contains("has no polygons")) << errors.first().toStdString();
  errors.clear();
}

// Sketch modelling (§3.2, §4.1): a wing moved, turned, grown and mirrored; after each the parts reconnect
// (one skeleton component, one watertight mesh), and the character exports in one step.
TEST_F(GuiWorkflow, SketchPartsMoveTurnMirrorAndReconnect) {
  open(dataPath("sketches/bird.txt"));  // body, then two wings
  SketchPanel* panel = window->sketchPanel();
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  const auto components = [](vtkPolyData* data) {
    auto regions = vtkSmartPointer<vtkPolyDataConnectivityFilter>::New();
    regions->SetInputData(data);
    regions->SetExtractionModeToAllRegions();
    regions->Update();
    return regions->GetNumberOfExtractedRegions();
  };
  const auto partNodes = [this](int part) {
    vtkPolyData* skeleton = object("bird.txt skeleton")->polyData();
    vtkDataArray* parts = skeleton->GetPointData()->GetArray("Part");
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (vtkIdType i = 0; i < skeleton->GetNumberOfPoints(); ++i)
      if (int(parts->GetComponent(i, 0)) == part) sum += Eigen::Vector3d(skeleton->GetPoint(i)), ++count;
    return Eigen::Vector3d(sum / std::max(count, 1));
  };
  const Eigen::Vector3d wing = partNodes(1);
  panel->setThresholdScope(1);
  ASSERT_TRUE(panel->movePart(1, 0, 2));
  panel->wait();
  EXPECT_GT((partNodes(1) - wing).norm(), 1.0) << "the wing's skeleton moved with it";
  ASSERT_TRUE(panel->turnPart(1, 1));
  panel->wait();
  ASSERT_TRUE(panel->scalePart(1, 1));
  panel->wait();
  EXPECT_EQ(components(object("bird.txt skeleton")->polyData()), 1) << "the wing reconnected to the body";
  EXPECT_EQ(components(object("bird.txt mesh")->polyData()), 1);
  // Mirrored across the body's plane: a fourth part, still one skeleton and one mesh.
  ASSERT_TRUE(panel->mirrorPart(1));
  panel->wait();
  EXPECT_EQ(object("bird.txt")->polyData()->GetNumberOfLines(), 4);
  EXPECT_EQ(int(object("bird.txt skeleton")->polyData()->GetPointData()->GetArray("Part")->GetRange()[1]), 3);
  EXPECT_EQ(components(object("bird.txt skeleton")->polyData()), 1);
  EXPECT_EQ(components(object("bird.txt mesh")->polyData()), 1);
  EXPECT_FALSE(panel->movePart(9, 1, 0)) << "no such part";
  const std::string rig = dir + "/bird-character.glb";
  ASSERT_TRUE(panel->exportCharacter(QString::fromStdString(rig))) << errors.join("\n").toStdString();
  const medial::RigSummary summary = medial::readRigSummary(rig);
  ASSERT_TRUE(summary.error.empty()) << summary.error;
  EXPECT_EQ(summary.unweightedVertices, 0);
  window->resetCamera();
  EXPECT_GT(screenshot("bird-mirrored"), 0.02);
}

// "Show steps" (issue 29): a run with "Record steps" on, then a slider over its intermediate results, each
// shown in the 3-D view; the contraction's iterations and the sketch's stages.
TEST_F(GuiWorkflow, ShowStepsStepsThroughTheStagesOfOneRun) {
  open(dataPath("meshes/torus.off"));
  SkeletonPanel* skeleton = window->skeletonPanel();
  skeleton->setRecordSteps(true);
  ASSERT_TRUE(runThroughUi(skeleton)) << errors.join("\n").toStdString();
  ASSERT_GE(skeleton->stepCount(), 4);
  EXPECT_TRUE(skeleton->stepName(0).contains("iteration 0"));
  EXPECT_TRUE(skeleton->stepName(skeleton->stepCount() - 1).contains("before the selection"));
  vtkIdType firstPoints = -1;
  double firstLength = 0, lastMeshLength = 0;
  for (int step = 0; step < skeleton->stepCount(); ++step) {
    ASSERT_TRUE(skeleton->showStep(step)) << step;
    SceneObject* shown = object("torus.off step");
    ASSERT_NE(shown, nullptr) << step;
    EXPECT_GT(shown->polyData()->GetNumberOfPoints(), 0) << step;
    if (step == 0)
      firstPoints = shown->polyData()->GetNumberOfPoints(), firstLength = shown->polyData()->GetLength();
    if (shown->polyData()->GetNumberOfPolys() > 0) lastMeshLength = shown->polyData()->GetLength();
  }
  EXPECT_EQ(firstPoints, object("torus.off")->polyData()->GetNumberOfPoints()) << "step 0 is the mesh itself";
  EXPECT_LT(lastMeshLength, firstLength) << "the contraction shrinks the mesh";
  EXPECT_FALSE(skeleton->showStep(skeleton->stepCount()));
  EXPECT_GT(screenshot("torus-contraction-step"), 0.01);

  // SQM's branch node polyhedra of the torus's skeleton, coloured by node.
  SqmPanel* sqm = window->sqmPanel();
  sqm->setInput(object("torus.off skeleton"));
  sqm->setRecordSteps(true);
  ASSERT_TRUE(runThroughUi(sqm)) << errors.join("\n").toStdString();
  ASSERT_EQ(sqm->stepCount(), 3);
  ASSERT_TRUE(sqm->showStep(2));
  SceneObject* base = object("torus.off skeleton step");
  ASSERT_NE(base, nullptr);
  vtkMapper* mapper = vtkActor::SafeDownCast(base->prop)->GetMapper();
  EXPECT_TRUE(mapper->GetScalarVisibility());
  EXPECT_STREQ(mapper->GetArrayName(), "SkeletonNode");

  open(dataPath("sketches/hand.txt"));
  SketchPanel* sketch = window->sketchPanel();
  sketch->setRecordSteps(true);
  ASSERT_TRUE(runThroughUi(sketch)) << errors.join("\n").toStdString();
  ASSERT_EQ(sketch->stepCount(), 5);
  EXPECT_EQ(sketch->stepName(0), "straight-skeleton");
  ASSERT_TRUE(sketch->showStep(1));
  EXPECT_GT(object("hand.txt step")->polyData()->GetNumberOfLines(), 0);
}

// The ghost view's controls of the paper's Fig. 2: importance levels per object, the conflict rule, and
// the importance map shown over the view.
TEST_F(GuiWorkflow, GhostImportanceLevelsConflictRuleAndMap) {
  open(dataPath("meshes/torus.off"));
  ASSERT_TRUE(runThroughUi(window->skeletonPanel())) << errors.join("\n").toStdString();
  SceneObject* skeleton = object("torus.off skeleton");
  ASSERT_TRUE(skeleton && skeleton->interest);
  window->objects()->setCurrent(skeleton);
  auto* importance = window->findChild<QSlider*>("objectImportance");
  ASSERT_NE(importance, nullptr);
  EXPECT_EQ(importance->value(), 10);
  importance->setValue(4);
  EXPECT_NEAR(vtkMedialGhostPass::GetImportance(skeleton->prop), 0.4, 1e-9);
  EXPECT_TRUE(skeleton->interest);
  importance->setValue(0);
  EXPECT_FALSE(skeleton->interest) << "importance 0 is context";
  window->objects()->setImportance(skeleton, 0.8);
  EXPECT_EQ(importance->value(), 8);

  auto* conflict = window->findChild<QComboBox*>("ghostConflict");
  ASSERT_NE(conflict, nullptr);
  conflict->setCurrentIndex(vtkMedialGhostPass::DepthSorting);
  EXPECT_EQ(window->scene()->GetGhostPass()->GetConflict(), vtkMedialGhostPass::DepthSorting);
  conflict->setCurrentIndex(vtkMedialGhostPass::GradualImportance);

  auto* map = window->findChild<QAction*>("importanceMap");
  ASSERT_NE(map, nullptr);
  EXPECT_TRUE(window->importanceMapImage().isNull()) << "no map kept before asked";
  map->setChecked(true);
  EXPECT_GT(screenshot("torus-importance-map"), 0.05);
  const QImage image = window->importanceMapImage();
  ASSERT_FALSE(image.isNull());
  int covered = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) covered += qAlpha(image.pixel(x, y)) > 100;
  EXPECT_GT(covered, image.width() * image.height() / 100) << "the skeleton's projection";
  EXPECT_LT(covered, image.width() * image.height() / 2);
  window->view()->grabFramebuffer().save(QString::fromStdString(dir + "/map-overlay.png"));
  map->setChecked(false);
}

TEST(GuiDialogs, UnreadableFileShowsAnErrorDialog) {
  if (!medial::test::hasDisplay()) GTEST_SKIP() << "no X display: run the tests under xvfb-run -a";
  MainWindow window;  // no error handler: errors go to a QMessageBox
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QString shown;
  QTimer::singleShot(200, [&shown] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
      shown = box->text();
      box->accept();
    }
  });
  EXPECT_FALSE(window.openFile("/nonexistent/ct.nii.gz"));
  EXPECT_TRUE(shown.contains("/nonexistent/ct.nii.gz")) << "dialog text: " << shown.toStdString();
  // The window still works afterwards.
  EXPECT_TRUE(window.openFile(QString::fromStdString(dataPath("meshes/torus.off"))));
  EXPECT_EQ(window.objectCount(), 1);
}

TEST_F(GuiWorkflow, DroppedFilesOpen) {
  QMimeData mime;
  mime.setUrls({QUrl::fromLocalFile(QString::fromStdString(dataPath("meshes/capsule.vtp"))),
                QUrl::fromLocalFile(QString::fromStdString(dataPath("skeletons/hand.swc")))});
  const QPoint at = window->rect().center();
  QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window.get(), &enter);
  EXPECT_TRUE(enter.isAccepted());
  QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window.get(), &drop);
  EXPECT_EQ(window->objectCount(), 2);
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}

// An interactive session leaves its layout (size, docks) for the next one.
TEST_F(GuiWorkflow, WindowLayoutIsRestoredInTheNextSession) {
  window->restoreLayout();
  auto* log = window->findChild<QDockWidget*>("logDock");
  ASSERT_TRUE(log);
  ASSERT_TRUE(log->isVisible());
  log->hide();
  window->resize(1100, 720);
  window->saveLayout();
  MainWindow next;
  next.restoreLayout();
  next.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&next));
  EXPECT_FALSE(next.findChild<QDockWidget*>("logDock")->isVisible());
  EXPECT_EQ(next.size(), QSize(1100, 720));
  QSettings("Medial", "medial-gui").remove("window");  // leave the user's settings as they were
}

// A full-size CT (512 x 512 x 400 int16, 210 MB) keeps the window responsive: it opens, its slices scroll
// at an interactive rate, and the centerline runs on the worker thread while the event loop keeps
// turning (a 20 ms timer goes on firing).
TEST_F(GuiWorkflow, FullSizeCtScrollsAndRunsTheCenterlineWithoutFreezing) {
  const std::string volume = dir + "/full-ct.mha";
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + "/full-ct " + volume + " --size 512x512x400 --no-dicom"));
  QElapsedTimer clock;
  clock.start();
  open(volume);
  const double openSeconds = clock.elapsed() / 1000.0;

  // Scrolling: the crosshair moved slice by slice, the axial view rendered each time (grabFramebuffer
  // renders the QOpenGLWidget at once and reads it back).
  auto cursor = window->sliceViews()->cursor();
  SliceView* axial = window->sliceViews()->view(2);
  ASSERT_FALSE(axial->grabFramebuffer().isNull());
  std::vector<double> frames;
  for (int k = 0; k < 40; ++k) {
    cursor[2] += 1.0;
    clock.restart();
    window->sliceViews()->setCursor(cursor);
    const QImage frame = axial->grabFramebuffer();
    frames.push_back(clock.nsecsElapsed() / 1e6);
    ASSERT_FALSE(frame.isNull());
  }
  std::nth_element(frames.begin(), frames.begin() + 20, frames.end());
  const double frameMs = frames[20];
  EXPECT_LT(frameMs, 100.0) << "median milliseconds to move the crosshair one slice and render it";

  // The centerline (threshold -1024..-600 HU, the panel's default window) with the event loop watched.
  CenterlinePanel* panel = window->centerlinePanel();
  window->filterTabs()->setCurrentIndex(2);
  panel->form()->setValue("Selection", 1);
  clock.restart();
  QTest::qWait(50);  // the tab's first paint (its chart) happens here, before the user can press Run
  const double tabMs = clock.elapsed() - 50.0;
  QElapsedTimer sinceTick;
  sinceTick.start();
  qint64 longestGapMs = 0;
  QTimer ticker;
  QObject::connect(&ticker, &QTimer::timeout, [&] {
    auto g = sinceTick.restart();
    if (g > 60)
      fprintf(stderr, "GAP %lld at %lld\n", (long long)g,
              (long long)(std::chrono::duration_cast<std::chrono::milliseconds>(
                              std::chrono::steady_clock::now().time_since_epoch())
                              .count() %
                          100000));
    longestGapMs = std::max(longestGapMs, g);
  });
  ticker.start(20);
  clock.restart();
  ASSERT_TRUE(runThroughUi(panel)) << errors.join("\n").toStdString();
  const double centerlineSeconds = clock.elapsed() / 1000.0;
  ticker.stop();
  EXPECT_LT(longestGapMs, 500) << "the window froze while the centerline ran";
  SceneObject* line = object("full-ct.mha centerline");
  ASSERT_NE(line, nullptr);
  EXPECT_GT(line->polyData()->GetNumberOfPoints(), 1000) << "a colon about 1 m long at 0.7 mm";
  std::printf(
      "full-size CT: opened in %.2f s, slice step %.1f ms (median of 40), centerline tab shown in %.0f ms, "
      "centerline with sections %.2f s, longest event-loop gap %lld ms\n",
      openSeconds, frameMs, tabMs, centerlineSeconds, static_cast<long long>(longestGapMs));
}

// medial-gui --run and --edit without --screenshot (issue 49): the window that stays open runs the filters
// in order and opens the last skeleton in the editor, as the --screenshot run does (gui/StartupActions).
TEST_F(GuiWorkflow, StartupRunAndEditWorkInTheWindowThatStaysOpen) {
  open(dataPath("meshes/torus.off"));
  bool finished = false, succeeded = false;
  auto* actions = new medial::gui::StartupActions(window.get(), {"skeleton"}, true, [&](bool ok) {
    finished = true;
    succeeded = ok;
  });
  actions->start();
  QElapsedTimer clock;
  clock.start();
  while (!finished && clock.elapsed() < 120000) QTest::qWait(20);
  ASSERT_TRUE(finished);
  EXPECT_TRUE(succeeded) << errors.join("\n").toStdString();
  EXPECT_FALSE(window->objects()->ofKind(SceneObject::Kind::Skeleton).empty());
  EXPECT_TRUE(window->skeletonEditor()->editing());
  // A filter that does not exist: done(false) at once, nothing run.
  finished = false;
  (new medial::gui::StartupActions(window.get(), {"no-such-filter"}, false, [&](bool ok) {
    finished = true;
    succeeded = ok;
  }))->start();
  while (!finished && clock.elapsed() < 130000) QTest::qWait(20);
  EXPECT_TRUE(finished);
  EXPECT_FALSE(succeeded);
}

// Issue 49: at the default 1024x768 the 3-D view keeps at least half the window's width, and no filter
// panel is wider than its dock (no horizontal scroll bar, "Done" not clipped).
TEST_F(GuiWorkflow, DefaultWindowLeavesHalfToThe3dViewAndNoPanelOverflows) {
  window->resize(1024, 768);
  QTest::qWait(100);
  EXPECT_GE(window->view()->width(), window->width() / 2)
      << "3-D view " << window->view()->width() << " of " << window->width() << " pixels";
  auto* tabs = window->findChild<QTabWidget*>("filters");
  ASSERT_TRUE(tabs);
  for (int i = 0; i < tabs->count(); ++i) {
    tabs->setCurrentIndex(i);
    QTest::qWait(30);
    auto* scroll = qobject_cast<QScrollArea*>(tabs->widget(i));
    ASSERT_TRUE(scroll) << tabs->tabText(i).toStdString();
    std::string tooWide;  // the widgets whose own minimum does not fit: those to make narrower
    for (QWidget* child : scroll->widget()->findChildren<QWidget*>())
      if (child->isVisible() && child->minimumSizeHint().width() > scroll->viewport()->width() - 12)
        tooWide += std::string(" ") + child->metaObject()->className() + " '" +
                   child->objectName().toStdString() + "' " +
                   std::to_string(child->minimumSizeHint().width()) + ";";
    EXPECT_FALSE(scroll->horizontalScrollBar()->isVisible())
        << tabs->tabText(i).toStdString() << ": panel " << scroll->widget()->minimumSizeHint().width()
        << " pixels wide in a viewport of " << scroll->viewport()->width() << "; too wide:" << tooWide;
  }
  // A closed dock comes back from View > Panels.
  auto* filters = window->findChild<QDockWidget*>("filtersDock");
  ASSERT_TRUE(filters);
  filters->toggleViewAction()->trigger();
  QTest::qWait(30);
  EXPECT_FALSE(filters->isVisible());
  filters->toggleViewAction()->trigger();
  EXPECT_TRUE(filters->isVisible());
}

// File > Open a Sample: the bundled samples and a colon CT phantom made on the spot.
TEST_F(GuiWorkflow, OpenASampleOpensBundledSamplesAndAColonPhantom) {
  QMenu* samples = nullptr;
  for (QMenu* menu : window->findChildren<QMenu*>())
    if (menu->title() == "Open a &Sample") samples = menu;
  ASSERT_TRUE(samples);
  ASSERT_EQ(samples->actions().size(), medial::gui::bundledSamples().size() + 1)
      << "a bundled sample is missing from " << medial::gui::sampleDirectory().toStdString();
  samples->actions().front()->trigger();  // the torus
  QTest::qWait(50);
  EXPECT_TRUE(object("torus.off")) << errors.join("\n").toStdString();
  samples->actions().back()->trigger();  // the colon phantom, a DICOM series
  QTest::qWait(50);
  EXPECT_FALSE(window->objects()->ofKind(SceneObject::Kind::Volume).empty())
      << errors.join("\n").toStdString();
  EXPECT_TRUE(errors.isEmpty()) << errors.join("\n").toStdString();
}
