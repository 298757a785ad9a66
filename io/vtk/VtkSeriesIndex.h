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

    // Records (or replaces) a frame's time and rewrites both index files —
    // unless deferred, when the files wait for write(): the processes of a
    // run that share its frames (`--distribute frames`) leave the index to
    // the first, once every frame exists.
    void add(int frame, double time);
    void setDeferred(bool deferred) { deferred_ = deferred; }
    void record(int frame, double time);
    void write() const;
    bool empty() const { return frameTimes_.empty(); }

private:
    std::filesystem::path directory_;
    std::string baseName_;
    std::string extension_;
    std::map<int, double> frameTimes_;  // ordered by frame
    bool deferred_ = false;
};

}  // namespace eikon::io
