// Structural checks run before a file reaches a VTK reader (internal to conescope_io).
//
// VTK's readers trust the files they read. vtkPLY indexes past its word list on short lines and
// mallocs from negative list counts (crashes, seen in tests); the STL and legacy readers allocate
// from the counts in the header, so a forged count in a tiny file asks for gigabytes; the XML
// reader dereferences a missing element when a cell array is bad. These checks
// reject such files first, with a message naming the file, so only well-formed data reaches VTK.
#pragma once

#include <string>

namespace conescope {

// Parses the PLY header and walks the whole body as vtkPLY will (one element per line in ASCII,
// fixed sizes and list counts in binary): every element present and complete, list counts
// non-negative, face indices within the vertex count, ASCII lines short enough for vtkPLY's line
// buffer. Throws MeshReadError ("path:line: what" for ASCII).
void checkPlyFile(const std::string& path);

// For files VTK will read as binary STL: throws MeshReadError if shorter than the 84-byte header,
// if the triangle count in the header exceeds what the file holds, or if it holds no triangle.
void checkStlFile(const std::string& path);

// Legacy .vtk: the POINTS and cell-list sizes declared in the file must fit in its size (two bytes
// per ASCII value, the type's size per binary value). Throws MeshReadError.
void checkLegacyVtkFile(const std::string& path);

// OBJ: every face/line/point corner is v, v/vt, v//vn or v/vt/vn with indices of elements that
// exist, and lines fit vtkOBJReader's buffer. Throws MeshReadError ("path:line: what").
void checkObjFile(const std::string& path);

// .vtp: checks the XML header (known array types, sane component counts, piece counts that fit
// the file) and returns the file's text with an empty <PointData/> added to pieces lacking one,
// which keeps vtkXMLPolyDataReader from crashing on a bad cell-data array. Throws MeshReadError.
std::string prepareVtpForVtk(const std::string& path);

}  // namespace conescope
