#include "io/vtk/VtkVolumeSource.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"

#include <nlohmann/json.hpp>
#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOpenFOAMReader.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProbeFilter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <utility>

namespace eikon::io {

namespace {

namespace fs = std::filesystem;

enum class Kind { XmlDataSet, Legacy, Collection, FileSeries, OpenFoam, PolyData, Unknown };

Kind kindOf(const fs::path& path) {
    if (fs::is_directory(path)) return Kind::OpenFoam;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".vtp") return Kind::PolyData;
    if (extension == ".vti" || extension == ".vtu" || extension == ".vts" || extension == ".vtr") return Kind::XmlDataSet;
    if (extension == ".vtk") return Kind::Legacy;
    if (extension == ".pvd") return Kind::Collection;
    if (extension == ".series") return Kind::FileSeries;
    if (extension == ".foam" || path.filename() == "controlDict") return Kind::OpenFoam;
    return Kind::Unknown;
}

[[noreturn]] void refuseSurface(const fs::path& file) {
    throw InputError(file.string(), "volume data (image data, an unstructured or structured grid, an OpenFOAM case)",
                     "polygonal data: a surface, which has no inside to sample (import it as a mesh object)");
}

// VTK's error reports of one reader or filter and its pipeline, taken by an
// observer instead of going to stderr, the first kept for the refusal.
class VtkErrors {
public:
    explicit VtkErrors(vtkAlgorithm& algorithm) : algorithm_(algorithm) {
        command_->SetClientData(&first_);
        command_->SetCallback([](vtkObject*, unsigned long, void* first, void* text) {
            auto& message = *static_cast<std::string*>(first);
            if (message.empty() && text) message = static_cast<const char*>(text);
        });
        onAlgorithm_ = algorithm_.AddObserver(vtkCommand::ErrorEvent, command_);
        onPipeline_ = algorithm_.GetExecutive()->AddObserver(vtkCommand::ErrorEvent, command_);
    }
    ~VtkErrors() {
        algorithm_.GetExecutive()->RemoveObserver(onPipeline_);
        algorithm_.RemoveObserver(onAlgorithm_);
    }
    VtkErrors(const VtkErrors&) = delete;
    VtkErrors& operator=(const VtkErrors&) = delete;

    bool any() const { return !first_.empty(); }
    // The report's last line (VTK puts its source file and line first).
    std::string message() const {
        std::string text = first_;
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
        const std::size_t line = text.find_last_of('\n');
        return line == std::string::npos ? text : text.substr(line + 1);
    }

private:
    vtkAlgorithm& algorithm_;
    vtkNew<vtkCallbackCommand> command_;
    std::string first_;
    unsigned long onAlgorithm_ = 0;
    unsigned long onPipeline_ = 0;
};

// Following a simulation, a read of a step its writer has not finished may
// fail (VolumeFollower.h) and is tried again: VTK's own report of it — from
// readers' inner XML parsers, which no observer sees — is kept off stderr
// while it reads; the refusal still names the step.
class QuietVtk {
public:
    explicit QuietVtk(bool quiet) : quiet_(quiet) {
        if (!quiet_) return;
        verbosity_ = vtkLogger::GetCurrentVerbosityCutoff();
        displayMode_ = vtkOutputWindow::GetInstance()->GetDisplayMode();
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
        vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
    }
    ~QuietVtk() {
        if (!quiet_) return;
        vtkOutputWindow::GetInstance()->SetDisplayMode(displayMode_);
        vtkLogger::SetStderrVerbosity(verbosity_);
    }
    QuietVtk(const QuietVtk&) = delete;
    QuietVtk& operator=(const QuietVtk&) = delete;

private:
    bool quiet_;
    vtkLogger::Verbosity verbosity_ = vtkLogger::VERBOSITY_WARNING;
    int displayMode_ = vtkOutputWindow::DEFAULT;
};

// One .vti/.vtu/.vts/.vtr or legacy .vtk file's data set.
vtkSmartPointer<vtkDataSet> readDataSetFile(const fs::path& file) {
    const Kind kind = kindOf(file);
    if (kind == Kind::PolyData) refuseSurface(file);
    if (kind != Kind::XmlDataSet && kind != Kind::Legacy)
        throw InputError(file.string(), "a VTK data set file (.vti, .vtu, .vts, .vtr or legacy .vtk)",
                         "\"" + file.extension().string() + "\"");
    if (!fs::is_regular_file(file)) throw InputError(file.string(), "an existing VTK file", "no such file");
    vtkSmartPointer<vtkDataObject> output;
    std::string error;
    if (kind == Kind::XmlDataSet) {
        vtkNew<vtkXMLGenericDataObjectReader> reader;
        reader->SetFileName(file.c_str());
        const VtkErrors errors(*reader);
        reader->Update();
        if (errors.any()) error = errors.message();
        output = reader->GetOutput();
    } else {
        vtkNew<vtkDataSetReader> reader;
        reader->SetFileName(file.c_str());
        const VtkErrors errors(*reader);
        reader->Update();
        if (errors.any()) error = errors.message();
        output = reader->GetOutput();
    }
    if (!error.empty() || !output) throw InputError(file.string(), "a VTK file VTK's reader reads", error.empty() ? "no data set" : error);
    if (vtkPolyData::SafeDownCast(output)) refuseSurface(file);
    vtkSmartPointer<vtkDataSet> dataset = vtkDataSet::SafeDownCast(output);
    if (!dataset || dataset->GetNumberOfCells() == 0)
        throw InputError(file.string(), "a data set with at least one cell", "none");
    return dataset;
}

// A .pvd's DataSet entries, ordered by timestep, relative to its folder.
std::vector<fs::path> collectionFiles(const fs::path& pvd) {
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(pvd.c_str());
    vtkNew<vtkCallbackCommand> swallow;  // the parser's own report would go to stderr
    parser->AddObserver(vtkCommand::ErrorEvent, swallow);
    vtkXMLDataElement* collection = nullptr;
    if (parser->Parse() == 1 && parser->GetRootElement())
        collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
    if (!collection)
        throw InputError(pvd.string(), "a VTK Collection file (<VTKFile type=\"Collection\"><Collection>…)",
                         "no Collection element that VTK's XML parser reads");
    std::vector<std::pair<double, fs::path>> steps;
    for (int e = 0; e < collection->GetNumberOfNestedElements(); ++e) {
        vtkXMLDataElement* entry = collection->GetNestedElement(e);
        if (std::string(entry->GetName()) != "DataSet") continue;
        const char* file = entry->GetAttribute("file");
        double time = e;
        if (!file || (entry->GetAttribute("timestep") && !entry->GetScalarAttribute("timestep", time)))
            throw InputError(pvd.string() + ": DataSet " + std::to_string(e),
                             "a file attribute and a numeric timestep", "neither or a bad one");
        steps.emplace_back(time, pvd.parent_path() / file);
    }
    std::stable_sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t s = 1; s < steps.size(); ++s)
        if (steps[s].first == steps[s - 1].first)
            throw InputError(pvd.string(), "one DataSet per timestep (a time series, not parts of one data set)",
                             "two at timestep " + formatRounded(steps[s].first));
    std::vector<fs::path> files;
    for (auto& step : steps) files.push_back(std::move(step.second));
    return files;
}

// A ParaView .series file's entries ({"files": [{"name", "time"}…]}), by time.
std::vector<fs::path> seriesFiles(const fs::path& series) {
    std::ifstream in(series);
    const nlohmann::json root = nlohmann::json::parse(in, nullptr, false);
    if (root.is_discarded() || !root.is_object() || !root.contains("files") || !root["files"].is_array())
        throw InputError(series.string(), "ParaView's file series JSON ({\"files\": [{\"name\": …, \"time\": …}, …]})",
                         "no such JSON");
    std::vector<std::pair<double, fs::path>> steps;
    for (const nlohmann::json& entry : root["files"]) {
        if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string() ||
            (entry.contains("time") && !entry["time"].is_number()))
            throw InputError(series.string() + ": files[" + std::to_string(steps.size()) + "]",
                             "{\"name\": string, \"time\": number}", entry.dump().substr(0, 80));
        const double time = entry.value("time", static_cast<double>(steps.size()));
        steps.emplace_back(time, series.parent_path() / entry["name"].get<std::string>());
    }
    std::stable_sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<fs::path> files;
    for (auto& step : steps) files.push_back(std::move(step.second));
    return files;
}

std::string listArrays(vtkDataSet& data) {
    std::string names;
    for (vtkFieldData* arrays : {static_cast<vtkFieldData*>(data.GetPointData()), static_cast<vtkFieldData*>(data.GetCellData())})
        for (int a = 0; a < arrays->GetNumberOfArrays(); ++a)
            if (const char* name = arrays->GetArrayName(a))
                names += (names.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    return names.empty() ? "no arrays" : "the arrays " + names;
}

// The OpenFOAM case's internal mesh at `time`.
vtkSmartPointer<vtkDataSet> readFoamStep(vtkOpenFOAMReader& reader, double time, const std::string& name) {
    const VtkErrors errors(reader);
    reader.UpdateTimeStep(time);
    vtkMultiBlockDataSet* blocks = reader.GetOutput();
    vtkDataSet* mesh = nullptr;
    for (unsigned b = 0; blocks && b < blocks->GetNumberOfBlocks(); ++b) {
        vtkInformation* meta = blocks->GetMetaData(b);
        if (meta && meta->Has(vtkCompositeDataSet::NAME()) &&
            std::string(meta->Get(vtkCompositeDataSet::NAME())) == "internalMesh")
            mesh = vtkDataSet::SafeDownCast(blocks->GetBlock(b));
    }
    if (errors.any() || !mesh || mesh->GetNumberOfCells() == 0)
        throw InputError(name, "an OpenFOAM internal mesh with cells that VTK's reader reads",
                         errors.any() ? errors.message() : "none");
    vtkSmartPointer<vtkDataSet> copy = vtkSmartPointer<vtkDataSet>::Take(mesh->NewInstance());
    copy->ShallowCopy(mesh);  // the reader reuses its output for the next step
    return copy;
}

// The probe's source: the data set's cells with the requested arrays only,
// point data before cell data of the same name. `name`: the step's, for a refusal.
vtkSmartPointer<vtkDataSet> requestedArrays(vtkDataSet& data, const std::vector<VtkArrayRequest>& requests,
                                            const std::string& name) {
    const vtkSmartPointer<vtkDataSet> source = vtkSmartPointer<vtkDataSet>::Take(data.NewInstance());
    source->CopyStructure(&data);
    for (const VtkArrayRequest& request : requests) {
        const bool onPoints = data.GetPointData()->GetArray(request.name.c_str()) != nullptr;
        vtkDataArray* array = onPoints ? data.GetPointData()->GetArray(request.name.c_str())
                                       : data.GetCellData()->GetArray(request.name.c_str());
        if (!array)
            throw InputError(name, "a point or cell array \"" + request.name + "\" (" + request.key + ")",
                             listArrays(data));
        if (array->GetNumberOfComponents() != 1 && array->GetNumberOfComponents() != 3)
            throw InputError(name + ": array \"" + request.name + "\"", "1 or 3 components",
                             std::to_string(array->GetNumberOfComponents()));
        if (onPoints) source->GetPointData()->AddArray(array);
        else source->GetCellData()->AddArray(array);
    }
    return source;
}

}  // namespace

bool isVtkVolumePath(const fs::path& path) {
    const Kind kind = kindOf(path);
    return kind != Kind::Unknown;
}

bool isVtkTimeSeriesPath(const fs::path& path) {
    const Kind kind = kindOf(path);
    return kind == Kind::Collection || kind == Kind::FileSeries || kind == Kind::OpenFoam;
}

struct VtkVolumeSource::Steps {
    Kind kind = Kind::Unknown;
    std::vector<fs::path> files;  // a data set file per step (an OpenFOAM case: none)
    vtkSmartPointer<vtkOpenFOAMReader> foam;
    std::vector<double> times;    // an OpenFOAM case's time directories
    std::vector<std::string> timeNames;  // … and their folders' names
    fs::path foamCase;

    // Step `step`'s data set; `name` is stepName's.
    vtkSmartPointer<vtkDataSet> read(int step, const std::string& name) const {
        const auto s = static_cast<std::size_t>(step);
        return foam ? readFoamStep(*foam, times.at(s), name) : readDataSetFile(files.at(s));
    }
};

VtkVolumeSource::VtkVolumeSource(const fs::path& path, bool following)
    : path_(path), following_(following), steps_(std::make_unique<Steps>()) {
    Steps& steps = *steps_;
    steps.kind = kindOf(path);
    switch (steps.kind) {
    case Kind::PolyData:
        refuseSurface(path);
    case Kind::Unknown:
        throw InputError(path.string(),
                         "a VTK volume (.vti, .vtu, .vts, .vtr, .vtk, a .pvd or .series time series) or an OpenFOAM "
                         "case (.foam, system/controlDict or its folder)",
                         "\"" + path.extension().string() + "\"");
    case Kind::XmlDataSet:
    case Kind::Legacy:
        steps.files = {path};
        break;
    case Kind::Collection:
    case Kind::FileSeries:
        listSteps();
        break;
    case Kind::OpenFoam: {
        const fs::path file = fs::is_directory(path) ? path / "system" / "controlDict" : path;
        if (!fs::is_regular_file(file))
            throw InputError(path.string(), "an OpenFOAM case (a .foam file or system/controlDict in the case folder)",
                             "no \"" + file.string() + "\"");
        steps.foamCase = file.filename() == "controlDict" ? file.parent_path().parent_path() : file.parent_path();
        steps.foam = vtkSmartPointer<vtkOpenFOAMReader>::New();
        steps.foam->SetFileName(file.c_str());
        steps.foam->SetCreateCellToPoint(0);  // cell data as the solver wrote it, constant per cell
        steps.foam->SetUse64BitFloats(true);  // binary fields as OpenFOAM's default (double) build writes them
        listSteps();
        break;
    }
    }
}

// The series' files or the case's time directories; following, what cannot
// be listed yet keeps the last list.
void VtkVolumeSource::listSteps() {
    Steps& steps = *steps_;
    if (steps.foam) {
        const QuietVtk quiet(following_);
        const VtkErrors errors(*steps.foam);
        steps.foam->SetRefresh();  // scan the time directories again
        steps.foam->UpdateInformation();
        std::vector<double> times;
        std::vector<std::string> names;
        vtkDoubleArray* values = steps.foam->GetTimeValues();
        vtkStringArray* folders = steps.foam->GetTimeNames();
        if (values && folders && folders->GetNumberOfValues() == values->GetNumberOfTuples())
            for (vtkIdType t = 0; t < values->GetNumberOfTuples(); ++t) {
                times.push_back(values->GetValue(t));
                names.push_back(folders->GetValue(t));
            }
        if (!following_ && (errors.any() || times.empty()))
            throw InputError(path_.string(), "an OpenFOAM case with at least one time directory that VTK's reader reads",
                             errors.any() ? errors.message() : "no time directories");
        if (errors.any()) return;
        steps.times = std::move(times);
        steps.timeNames = std::move(names);
        return;
    }
    if (steps.kind != Kind::Collection && steps.kind != Kind::FileSeries) return;
    std::vector<fs::path> files;
    try {
        if (!fs::is_regular_file(path_)) throw InputError(path_.string(), "an existing time series file", "no such file");
        files = steps.kind == Kind::Collection ? collectionFiles(path_) : seriesFiles(path_);
    } catch (const InputError&) {
        if (following_) return;  // not written yet, or being rewritten
        throw;
    }
    if (files.empty() && !following_)
        throw InputError(path_.string(), "a time series of at least one file", "none listed");
    for (const fs::path& file : files) {
        if (kindOf(file) == Kind::PolyData) refuseSurface(file);
        if (!following_ && !fs::is_regular_file(file))
            throw InputError(path_.string(), "every file the series lists", "\"" + file.string() + "\" missing");
    }
    steps.files = std::move(files);
}

void VtkVolumeSource::refresh() {
    EIKON_CHECK_MSG(following_, "refresh on a VTK source not opened to follow");
    listSteps();
}

std::vector<fs::path> VtkVolumeSource::stepFiles(int step, const std::vector<VtkArrayRequest>& requests) const {
    const auto s = static_cast<std::size_t>(step);
    if (!steps_->foam) return {steps_->files.at(s)};
    const fs::path folder = steps_->foamCase / steps_->timeNames.at(s);
    std::vector<fs::path> files;
    for (const VtkArrayRequest& request : requests) {
        const fs::path compressed = folder / (request.name + ".gz");
        files.push_back(fs::exists(compressed) ? compressed : folder / request.name);
    }
    return files;
}

VtkVolumeSource::~VtkVolumeSource() = default;
VtkVolumeSource::VtkVolumeSource(VtkVolumeSource&&) noexcept = default;
VtkVolumeSource& VtkVolumeSource::operator=(VtkVolumeSource&&) noexcept = default;

int VtkVolumeSource::stepCount() const {
    return static_cast<int>(steps_->foam ? steps_->times.size() : steps_->files.size());
}

std::string VtkVolumeSource::stepName(int step) const {
    const auto s = static_cast<std::size_t>(step);
    if (steps_->foam) return steps_->foamCase.string() + " at time " + formatRounded(steps_->times.at(s));
    return steps_->files.at(s).string();
}

void VtkVolumeSource::check(int step, const std::vector<VtkArrayRequest>& requests) const {
    const QuietVtk quiet(following_);
    requestedArrays(*steps_->read(step, stepName(step)), requests, stepName(step));
}

VtkResampled VtkVolumeSource::resample(int step, const std::vector<VtkArrayRequest>& requests, const GridSpec& grid,
                                       const glm::dmat4& placement) const {
    const std::string name = stepName(step);
    const QuietVtk quiet(following_);
    const vtkSmartPointer<vtkDataSet> source = requestedArrays(*steps_->read(step, name), requests, name);

    // Each render cell centre in the file's world.
    const glm::dmat4 toFile = glm::inverse(placement);
    vtkNew<vtkPoints> centres;
    centres->SetDataTypeToDouble();
    centres->SetNumberOfPoints(static_cast<vtkIdType>(grid.cellCount()));
    vtkIdType id = 0;
    for (int k = 0; k < grid.resolution.z; ++k)
        for (int j = 0; j < grid.resolution.y; ++j)
            for (int i = 0; i < grid.resolution.x; ++i) {
                const glm::dvec4 p = toFile * glm::dvec4(grid.cellCentre(i, j, k), 1.0);
                centres->SetPoint(id++, p.x, p.y, p.z);
            }
    vtkNew<vtkPolyData> probes;
    probes->SetPoints(centres);

    vtkNew<vtkProbeFilter> probe;
    probe->SetInputData(probes);
    probe->SetSourceData(source);
    vtkNew<vtkStaticCellLocator> locator;  // a cell locator finds the cell holding each centre in any mesh
    probe->SetCellLocatorPrototype(locator);
    probe->PassPointArraysOff();
    probe->PassCellArraysOff();
    probe->PassFieldArraysOff();
    const VtkErrors errors(*probe);
    probe->Update();
    vtkDataSet* probed = probe->GetOutput();
    vtkDataArray* valid = probed ? probed->GetPointData()->GetArray(probe->GetValidPointMaskArrayName()) : nullptr;
    if (errors.any() || !valid)
        throw InputError(name, "data VTK's probe filter resamples", errors.any() ? errors.message() : "no output");

    VtkResampled resampled;
    const std::size_t cells = grid.cellCount();
    resampled.covered.resize(cells);
    for (std::size_t c = 0; c < cells; ++c)
        resampled.covered[c] = valid->GetComponent(static_cast<vtkIdType>(c), 0) != 0.0 ? 1 : 0;
    for (const VtkArrayRequest& request : requests) {
        vtkDataArray* array = probed->GetPointData()->GetArray(request.name.c_str());
        if (!array) throw InputError(name, "the probe filter's array \"" + request.name + "\"", "none");
        VtkResampled::Array out;
        out.components = array->GetNumberOfComponents();
        out.values.assign(cells * static_cast<std::size_t>(out.components), 0.0f);
        for (std::size_t c = 0; c < cells; ++c) {
            if (!resampled.covered[c]) continue;
            for (int a = 0; a < out.components; ++a) {
                const double value = array->GetComponent(static_cast<vtkIdType>(c), a);
                if (!std::isfinite(value)) {
                    const double* at = centres->GetPoint(static_cast<vtkIdType>(c));
                    throw InputError(name + ": array \"" + request.name + "\" (" + request.key + ")",
                                     "finite values", formatRounded(value) + " at " +
                                                          formatPosition(glm::dvec3(at[0], at[1], at[2])) +
                                                          " in the file's world");
                }
                out.values[c * static_cast<std::size_t>(out.components) + static_cast<std::size_t>(a)] =
                    static_cast<float>(value);
            }
        }
        resampled.arrays.push_back(std::move(out));
    }
    return resampled;
}

}  // namespace eikon::io
