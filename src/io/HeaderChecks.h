// Structural checks run before a file reaches a VTK reader (internal to conescope_io).
//
// VTK 9.1's readers trust the files they read, and mutated copies of valid files crashed every one
// of them except the STL reader: the legacy reader crashes on a file cut inside a cell list or
// holding a value its type cannot hold, and zero-fills truncated attribute data; the XML reader
// dereferences a missing <PointData> when a cell array is bad and trusts appended block tables;
// vtkPLY indexed past its word list on short lines and vtkOBJReader crashed on a corner "1/", which
// is why PLY and OBJ are read by hand now (PlyFormat.h, ObjFormat.h). The STL and legacy readers
// also allocate from header counts, so a forged count in a tiny file asks for gigabytes. These
// checks reject such files first, with a message naming the file (and line, for text formats), so
// only well-formed data reaches VTK. tests/io/MutationTests.cpp keeps them honest.
#pragma once

#include <string>

namespace conescope {

// For files VTK will read as binary STL, and text files without ASCII STL's 'solid': throws
// MeshReadError if shorter than the 84-byte header, if the triangle count in the header differs
// from the whole triangles the file holds (a remainder under 50 bytes is allowed), or if it is 0.
void checkStlFile(const std::string& path);

// Legacy .vtk POLYDATA: walks every section as vtkPolyDataReader will (exact keywords, every
// declared value present and representable in its type, cell lists consistent with their counts,
// attribute data complete, no values beyond a declared count), streaming through the data without
// allocating from counts. Throws MeshReadError.
void checkLegacyVtkFile(const std::string& path);

// .vtp: reads the XML with expat (up to <AppendedData>, whose data may be raw binary, as VTK
// does) and checks it: well-formed, read by VTK as the XML says (array data are plain text; no '>'
// in a DataArray's attribute values; no stray "<AppendedData"; not UTF-16), known array types,
// sane component counts, piece counts that fit the file; then every array in every encoding
// (ASCII, inline base64, raw or base64 appended, compressed or not, told apart as VTK does; an
// offset attribute only with format="appended"): no more values than the piece counts give (for
// binary arrays, exactly as many), binary headers and block tables that fit the data in the file,
// and each cell section's last offset equal to the length of its connectivity.
// Returns the file's text with an empty <PointData/> added to pieces lacking one, which keeps
// vtkXMLPolyDataReader from crashing on a bad cell-data array. Throws MeshReadError
// ("path:line: what").
std::string prepareVtpForVtk(const std::string& path);

}  // namespace conescope
