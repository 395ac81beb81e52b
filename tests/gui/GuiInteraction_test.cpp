// The 3-D view answers the mouse and the keyboard: QTest sends real Qt events to the widget and the
// camera is checked (run under xvfb-run: QOpenGLWidget needs an X server).
#include "TestPaths.h"

#include "MainWindow.h"
#include "VtkView.h"
#include "vtkMedialScene.h"

#include <QApplication>
#include <QMouseEvent>
#include <QTest>

#include <vtkCamera.h>
#include <vtkMath.h>
#include <vtkRenderer.h>

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
