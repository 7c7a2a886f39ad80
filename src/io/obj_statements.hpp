// OBJ text as CGAL's reader takes it. The format allows what that reader refuses: a statement
// continued over lines ending in a backslash (Blender and others write long faces so), and
// polylines ('l'), which a surface remesher ignores as it ignores points; and faces whose
// corners are separated by tabs, which it misreads (it skips to the next space after each
// corner's vertex id).
#pragma once

#include <istream>
#include <string>

namespace cvtmesh {

// The statements of `in`, each on one line, without the polylines, with single spaces between
// the corners of a face that has other blanks between them.
std::string obj_for_cgal(std::istream& in);

}  // namespace cvtmesh
