// Shared pieces of the VTK XML writers: compressed binary settings, atomic writing with VTK's
// error reported as an OutputError, and named arrays.
#pragma once

#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>
#include <vtkXMLWriter.h>

#include <filesystem>

namespace slides {

/// Writes with zlib-compressed appended binary data to a temporary, then renames it to file.
void writeVtkAtomically(const std::filesystem::path& file, vtkXMLWriter* writer);

/// A double array named name with the given components and tuples.
vtkSmartPointer<vtkDoubleArray> namedDoubleArray(const char* name, int components,
                                                 vtkIdType tuples);

} // namespace slides
