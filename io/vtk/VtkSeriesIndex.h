// The two index files ParaView reads for a time series of VTK XML files:
// DIR/NAME.pvd (a VTK "Collection") and DIR/NAME.EXT.series (ParaView's JSON
// file-series sidecar), both listing every frame's file with its time and
// rewritten atomically whenever a frame is added, so ParaView can open a
// run that is still going.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace eikon::io {

// Letters, digits, '_', '-' and '.' only (names land unescaped in XML and JSON).
bool isSafeVtkBaseName(const std::string& name);

class VtkSeriesIndex {
public:
    // Frame files are DIR/NAME_NNNNN.EXT; `extension` without the dot ("vti", "vtp").
    VtkSeriesIndex(std::filesystem::path directory, std::string baseName, std::string extension);

    std::filesystem::path framePath(int frame) const;
    std::filesystem::path collectionPath() const;  // NAME.pvd
    std::filesystem::path seriesPath() const;      // NAME.EXT.series

    // Records (or replaces) a frame's time and rewrites both index files.
    void add(int frame, double time);

private:
    std::filesystem::path directory_;
    std::string baseName_;
    std::string extension_;
    std::map<int, double> frameTimes_;  // ordered by frame
};

}  // namespace eikon::io
