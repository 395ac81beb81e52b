// The 3-D view answers the mouse and the keyboard: QTest sends real Qt events to the widget and the
// camera is checked (run under xvfb-run: QOpenGLWidget needs an X server).
#include "TestPaths.h"

#include "MainWindow.h"
#include "ObjectList.h"
#include "SkeletonEditor.h"
#include "ViewGeometry.h"
#include "VtkView.h"
#include "vtkMedialScene.h"

#include <QApplication>
#include <QMouseEvent>
#include <QTest>
#include <QUndoStack>

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <array>
#include <memory>

// The QApplication is made by tests/gui/main.cpp.

namespace {

using Vector = std::array<double, 3>;

class GuiInteraction : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!medial::test::hasDisplay()) GTEST_SKIP() << "no X display: run the tests under xvfb-run -a";
    window = std::make_unique<medial::gui::MainWindow>();
    window->setErrorHandler([this](const QString&, const QString& message) { lastError = message; });
    window->resize(800, 600);
    ASSERT_TRUE(window->openFile(QString::fromStdString(medial::test::dataPath("meshes/torus.off"))));
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    view = window->view();
    QTest::qWait(50);
  }

  vtkCamera* camera() { return window->scene()->GetRenderer()->GetActiveCamera(); }
  Vector position() {
    return {camera()->GetPosition()[0], camera()->GetPosition()[1], camera()->GetPosition()[2]};
  }
  Vector focal() {
    return {camera()->GetFocalPoint()[0], camera()->GetFocalPoint()[1], camera()->GetFocalPoint()[2]};
  }
  double distance() { return camera()->GetDistance(); }

  // A press, a few moves and a release, as a user's drag.
  void drag(Qt::MouseButton button, QPoint from, QPoint to,
            Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QTest::mousePress(view, button, modifiers, from);
    for (int step = 1; step <= 5; ++step) {
      const QPoint at = from + (to - from) * step / 5;
      QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, button, modifiers);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, button, modifiers, to);
  }

  std::unique_ptr<medial::gui::MainWindow> window;
  medial::gui::VtkView* view = nullptr;
  QString lastError;
};

double separation(const Vector& a, const Vector& b) {
  return std::sqrt(vtkMath::Distance2BetweenPoints(a.data(), b.data()));
}

}  // namespace

TEST_F(GuiInteraction, LeftDragRotatesAroundTheFocalPoint) {
  const Vector before = position();
  const double radius = distance();
  const QPoint centre = view->rect().center();
  drag(Qt::LeftButton, centre, centre + QPoint(120, 40));
  EXPECT_GT(separation(before, position()), 0.1 * radius) << "the camera did not move";
  EXPECT_NEAR(distance(), radius, 1e-6 * radius) << "rotation changed the distance";
}

TEST_F(GuiInteraction, MiddleDragPans) {
  const Vector before = focal();
  const QPoint centre = view->rect().center();
  drag(Qt::MiddleButton, centre, centre + QPoint(100, 0));
  EXPECT_GT(separation(before, focal()), 1e-3) << "the focal point did not move";
}

TEST_F(GuiInteraction, WheelZooms) {
  const double before = distance();
  const QPoint centre = view->rect().center();
  QWheelEvent forward(centre, view->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(view, &forward);
  EXPECT_LT(distance(), 0.95 * before);
  QWheelEvent backward(centre, view->mapToGlobal(centre), QPoint(), QPoint(0, -240), Qt::NoButton,
                       Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(view, &backward);
  EXPECT_GT(distance(), before);
}

TEST_F(GuiInteraction, KeyRResetsTheCamera) {
  const Vector home = position();
  const QPoint centre = view->rect().center();
  drag(Qt::LeftButton, centre, centre + QPoint(150, -60));
  ASSERT_GT(separation(home, position()), 1e-3);
  QTest::keyClick(view, Qt::Key_R);
  EXPECT_LT(separation(home, position()), 1e-6 * distance());
}

TEST_F(GuiInteraction, FailedOpenLeavesTheSessionIntact) {
  EXPECT_FALSE(window->openFile("/nonexistent/file.vtp"));
  EXPECT_TRUE(lastError.contains("/nonexistent/file.vtp")) << lastError.toStdString();
  EXPECT_EQ(window->objectCount(), 1);
  const std::string png = medial::test::scratchDir("gui-after-error") + "/still.png";
  EXPECT_TRUE(window->saveScreenshot(QString::fromStdString(png)));
}

namespace {

// The mean position of the mesh vertices made for `node` (point data SkeletonNode).
Eigen::Vector3d vertexCentroidOf(vtkPolyData* mesh, int node) {
  vtkDataArray* owner = mesh->GetPointData()->GetArray("SkeletonNode");
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (vtkIdType v = 0; owner && v < mesh->GetNumberOfPoints(); ++v)
    if (int(owner->GetComponent(v, 0)) == node) sum += Eigen::Vector3d(mesh->GetPoint(v)), ++count;
  return count ? Eigen::Vector3d(sum / count) : Eigen::Vector3d::Constant(NAN);
}

}  // namespace

// The SQM paper's §6 editor driven with real mouse events: a node dragged, the mesh around it follows;
// a new branch, a split edge, a radius from the wheel, a deletion; each undone.
TEST_F(GuiInteraction, SkeletonEditorDragsANodeAndItsMeshFollows) {
  using medial::gui::SkeletonEditor;
  ASSERT_TRUE(window->openFile(QString::fromStdString(medial::test::dataPath("skeletons/sqm/humanoid.vtp"))));
  medial::gui::SceneObject* humanoid = window->objects()->findByName("humanoid.vtp");
  ASSERT_NE(humanoid, nullptr);
  window->objects()->setVisible(window->objects()->findByName("torus.off"), false);
  SkeletonEditor* editor = window->skeletonEditor();
  ASSERT_TRUE(editor->begin(humanoid)) << lastError.toStdString();
  window->resetCamera();
  QTest::qWait(50);
  const medial::Skeleton original = editor->skeleton();
  const std::vector<int> degrees = medial::nodeDegrees(original);
  const int leaf = int(std::find(degrees.begin(), degrees.end(), 1) - degrees.begin());
  ASSERT_LT(leaf, original.nodeCount());
  vtkRenderer* renderer = window->scene()->GetRenderer();
  const QPoint at = medial::gui::widgetPosition(renderer, view, original.nodes[size_t(leaf)]).toPoint();
  const Eigen::Vector3d meshBefore = vertexCentroidOf(editor->mesh(), leaf);
  ASSERT_TRUE(meshBefore.allFinite());
  const Vector cameraBefore = position();

  drag(Qt::LeftButton, at, at + QPoint(40, -30));
  const Eigen::Vector3d moved = editor->skeleton().nodes[size_t(leaf)] - original.nodes[size_t(leaf)];
  const double size = editor->mesh()->GetLength();
  EXPECT_GT(moved.norm(), 0.02 * size) << "the node did not follow the pointer";
  EXPECT_LT(separation(cameraBefore, position()), 1e-9) << "the drag turned the camera instead";
  const Eigen::Vector3d meshMoved = vertexCentroidOf(editor->mesh(), leaf) - meshBefore;
  // The leaf's ring turns with its tube, so its vertices move less than the node, but the same way.
  EXPECT_GT(meshMoved.dot(moved.normalized()), 0.5 * moved.norm()) << "the mesh did not follow the node";
  EXPECT_EQ(editor->undoStack()->count(), 1);
  EXPECT_GT(editor->lastMeshMilliseconds(), 0);

  // The wheel over the node grows its radius by 10 % a notch; two notches merge into one undo step.
  const double radius = editor->skeleton().radii[size_t(leaf)];
  const QPoint there =
      medial::gui::widgetPosition(renderer, view, editor->skeleton().nodes[size_t(leaf)]).toPoint();
  for (int notch = 0; notch < 2; ++notch) {
    QWheelEvent wheel(there, view->mapToGlobal(there), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
  }
  EXPECT_NEAR(editor->skeleton().radii[size_t(leaf)], radius * 1.21, 1e-9 * radius);
  EXPECT_EQ(editor->undoStack()->count(), 2);

  // Shift+drag from the node: a new branch; Ctrl+click on an edge's middle: a new node; Delete: one less.
  drag(Qt::LeftButton, there, there + QPoint(30, 30), Qt::ShiftModifier);
  EXPECT_EQ(editor->skeleton().nodeCount(), original.nodeCount() + 1);
  EXPECT_EQ(editor->skeleton().edgeCount(), original.edgeCount() + 1);
  // The edge longest on screen, so that its middle is no node's.
  Eigen::Vector3d middle = Eigen::Vector3d::Zero();
  double longest = 0;
  for (const auto& edge : editor->skeleton().edges) {
    const Eigen::Vector3d a = editor->skeleton().nodes[size_t(edge[0])],
                          b = editor->skeleton().nodes[size_t(edge[1])];
    const QPointF ends =
        medial::gui::widgetPosition(renderer, view, a) - medial::gui::widgetPosition(renderer, view, b);
    if (std::hypot(ends.x(), ends.y()) > longest)
      longest = std::hypot(ends.x(), ends.y()), middle = 0.5 * (a + b);
  }
  ASSERT_GT(longest, 40);
  QTest::mouseClick(view, Qt::LeftButton, Qt::ControlModifier,
                    medial::gui::widgetPosition(renderer, view, middle).toPoint());
  EXPECT_EQ(editor->skeleton().nodeCount(), original.nodeCount() + 2);
  QTest::keyClick(view, Qt::Key_Delete);
  EXPECT_EQ(editor->skeleton().nodeCount(), original.nodeCount() + 1);
  EXPECT_GT(editor->mesh()->GetNumberOfPolys(), 0);

  // Undo everything: the skeleton is the original again; redo the first step.
  while (editor->undoStack()->canUndo()) editor->undoStack()->undo();
  EXPECT_EQ(editor->skeleton().nodes, original.nodes);
  EXPECT_EQ(editor->skeleton().radii, original.radii);
  editor->undoStack()->redo();
  EXPECT_GT((editor->skeleton().nodes[size_t(leaf)] - original.nodes[size_t(leaf)]).norm(), 0.02 * size);

  // Saved as VTP and SWC; Done adds the skeleton and its mesh as objects.
  const std::string dir = medial::test::scratchDir("skeleton-editor");
  EXPECT_TRUE(editor->save(QString::fromStdString(dir + "/edited.vtp")));
  EXPECT_TRUE(editor->save(QString::fromStdString(dir + "/edited.swc")));
  editor->finish();
  EXPECT_FALSE(editor->editing());
  EXPECT_NE(window->objects()->findByName("humanoid.vtp edited"), nullptr);
  EXPECT_NE(window->objects()->findByName("humanoid.vtp edited SQM"), nullptr);
  // The mouse turns the camera again.
  drag(Qt::LeftButton, view->rect().center(), view->rect().center() + QPoint(100, 0));
  EXPECT_GT(separation(cameraBefore, position()), 1e-6);
}
