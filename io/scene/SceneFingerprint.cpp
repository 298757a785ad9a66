#include "io/scene/SceneFingerprint.h"

#include <vtksys/MD5.h>

#include <array>

namespace eikon {

std::string sceneFingerprint(const nlohmann::json& document) {
    nlohmann::json rendered = document;
    if (rendered.is_object()) {
        rendered.erase("camera");
        rendered.erase("export");
    }
    const std::string text = rendered.dump();  // nlohmann::json keeps an object's keys sorted
    vtksysMD5* md5 = vtksysMD5_New();
    vtksysMD5_Initialize(md5);
    vtksysMD5_Append(md5, reinterpret_cast<const unsigned char*>(text.data()), static_cast<int>(text.size()));
    std::array<char, 32> hex{};
    vtksysMD5_FinalizeHex(md5, hex.data());
    vtksysMD5_Delete(md5);
    return std::string(hex.data(), hex.size());
}

}  // namespace eikon
