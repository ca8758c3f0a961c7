// Any bytes given to the OFF parser either become a valid mesh or a MeshReadError: never a crash,
// a hang, or an allocation driven by a forged count.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/Mesh.h"
#include "io/MeshReader.h"
#include "io/OffFormat.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const conescope::Mesh mesh =
            conescope::parseOff(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.off");
        if (mesh.faceCount() == 0) __builtin_trap();  // the parser promises at least one face
        conescope::validateMesh(mesh);
    } catch (const conescope::MeshReadError&) {
    } catch (const std::runtime_error&) {  // validateMesh's verdict on a parsed mesh
    }
    return 0;
}
