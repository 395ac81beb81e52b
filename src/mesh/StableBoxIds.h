/// \file
/// StableBoxIds: CGAL's corefinement and autorefinement (intersection_impl.h) order the boxes of faces and
/// edges by their addresses (Box_intersection_d::ID_FROM_BOX_ADDRESS) where their coordinates tie, and the
/// face boxes and the edge boxes live in two vectors whose relative place depends on the heap: the same
/// mesh gave another union when the process had made threads before (the crossing tubes refined twice:
/// 3322 faces in a fresh process, 3329 after, SqmUnionFilter.TheSameInputGivesTheSameUnion). Here the boxes
/// of Surface_mesh halfedges take CGAL's ID_EXPLICIT numbers instead, given in creation order (faces, then
/// edges): the same order in every run. Include this before CGAL's headers in every file that includes
/// Polygon_mesh_processing/corefinement.h (one definition of the box type per program); self_intersections.h
/// keeps its face boxes in one vector, whose addresses follow the faces' order, and needs nothing.
#pragma once

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>

namespace CGAL::Box_intersection_d {

template <>
class Box_with_info_d<double, 3, SM_Halfedge_index, ID_FROM_BOX_ADDRESS>
    : public Box_with_info_d<double, 3, SM_Halfedge_index, ID_EXPLICIT> {
 public:
  using Box_with_info_d<double, 3, SM_Halfedge_index, ID_EXPLICIT>::Box_with_info_d;
};

}  // namespace CGAL::Box_intersection_d
