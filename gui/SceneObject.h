// SceneObject: one row of the object list: data read from a file or computed by a filter, and the prop
// that shows it in the 3-D view.
#pragma once

#include <QString>

#include <vtkDataObject.h>
#include <vtkPolyData.h>
#include <vtkProp3D.h>
#include <vtkSmartPointer.h>

namespace medial::gui {

struct SceneObject {
  enum class Kind { Mesh, Skeleton, Volume, Sketch };

  QString name;
  QString path;  // the file it came from; empty for computed objects
  Kind kind = Kind::Mesh;
  vtkSmartPointer<vtkDataObject> data;
  vtkSmartPointer<vtkProp3D> prop;
  bool interest = false;  // object of interest of the ghost view
  // A contraction skeleton's mesh with `SkinWeights` (port 1 of the filter): what a rig export needs.
  vtkSmartPointer<vtkPolyData> skinnedMesh;

  vtkPolyData* polyData() const { return vtkPolyData::SafeDownCast(data); }
};

QString kindName(SceneObject::Kind kind);

}  // namespace medial::gui
