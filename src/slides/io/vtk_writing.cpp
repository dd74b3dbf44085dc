#include "slides/io/vtk_writing.h"

#include "slides/io/atomic_file.h"

#include <vtkErrorCode.h>
#include <vtkObject.h>

namespace slides {

void writeVtkAtomically(const std::filesystem::path& file, vtkXMLWriter* writer) {
    writer->SetDataModeToAppended();
    writer->SetCompressorTypeToZLib();
    writer->EncodeAppendedDataOff();
    writeFileAtomically(file, [&](const std::filesystem::path& temporary) {
        writer->SetFileName(temporary.c_str());
        // A failure becomes the one OutputError below, not VTK's multi-line pipeline report.
        const bool warnings = vtkObject::GetGlobalWarningDisplay();
        vtkObject::GlobalWarningDisplayOff();
        const int written = writer->Write();
        vtkObject::SetGlobalWarningDisplay(warnings);
        if (written != 1 || writer->GetErrorCode() != 0)
            throw OutputError("cannot write " + file.string() + ": VTK writer failed (" +
                              std::string(vtkErrorCode::GetStringFromErrorCode(
                                  static_cast<int>(writer->GetErrorCode()))) +
                              ")");
    });
}

vtkSmartPointer<vtkDoubleArray> namedDoubleArray(const char* name, int components,
                                                 vtkIdType tuples) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(tuples);
    return array;
}

} // namespace slides
