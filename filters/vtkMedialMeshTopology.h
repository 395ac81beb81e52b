/// \class vtkMedialMeshTopology
/// \brief Tells whether a polygon mesh is a closed 2-manifold, how many components it has and its genus.
///
/// The output is the input (shallow copy) with field data arrays `Genus`, `EulerCharacteristic`,
/// `Components`, `BorderEdges`, `NonManifoldEdges`, `BoundaryLoops`; the same values are available through
/// the getters after an update. Polygons and triangle strips count as faces; lines and vertices are
/// ignored. Genus is the sum over components of (2 - chi - b) / 2, meaningful for manifold meshes.
/// With CountSelfIntersections on, it also counts the pairs of faces that cut each other (CGAL's exact
/// test, src/mesh/SelfIntersections.h; field array `IntersectingFacePairs`): a closed manifold whose faces
/// cut each other bounds no volume (what SQM's union and Blender's Skin modifier are compared on).
/// Implements medial::computeMeshTopology (src/mesh/MeshTopology.h).
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class MEDIALFILTERS_EXPORT vtkMedialMeshTopology : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialMeshTopology* New();
  vtkTypeMacro(vtkMedialMeshTopology, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// After an update: the counts of medial::MeshTopology (faces, edges, border and non-manifold edges,
  /// components, boundary loops, Euler characteristic, genus).
  vtkGetMacro(NumberOfFaces, vtkIdType);
  vtkGetMacro(NumberOfEdges, vtkIdType);
  vtkGetMacro(NumberOfBorderEdges, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfComponents, vtkIdType);
  vtkGetMacro(NumberOfBoundaryLoops, vtkIdType);
  vtkGetMacro(EulerCharacteristic, vtkIdType);
  vtkGetMacro(Genus, vtkIdType);
  ///@}
  /// No border and no non-manifold edge, and at least one face.
  vtkGetMacro(ClosedManifold, bool);

  ///@{
  /// Also count the pairs of faces that cut each other (off by default: n log n, but far slower than the
  /// rest). Default false.
  vtkSetMacro(CountSelfIntersections, bool);
  vtkGetMacro(CountSelfIntersections, bool);
  vtkBooleanMacro(CountSelfIntersections, bool);
  ///@}
  /// Pairs of faces that cut each other (faces sharing a vertex or an edge only where they overlap beyond
  /// it); -1 when not counted.
  vtkGetMacro(NumberOfIntersectingFacePairs, vtkIdType);

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialMeshTopology() = default;
  ~vtkMedialMeshTopology() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialMeshTopology(const vtkMedialMeshTopology&) = delete;
  void operator=(const vtkMedialMeshTopology&) = delete;

  vtkIdType NumberOfFaces = 0;
  vtkIdType NumberOfEdges = 0;
  vtkIdType NumberOfBorderEdges = 0;
  vtkIdType NumberOfNonManifoldEdges = 0;
  vtkIdType NumberOfComponents = 0;
  vtkIdType NumberOfBoundaryLoops = 0;
  vtkIdType EulerCharacteristic = 0;
  vtkIdType Genus = 0;
  bool ClosedManifold = false;
  bool CountSelfIntersections = false;
  vtkIdType NumberOfIntersectingFacePairs = -1;
};
