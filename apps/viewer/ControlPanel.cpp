#include "apps/viewer/ControlPanel.h"

#include <imgui.h>

#include <glm/common.hpp>

namespace eikon::view {

namespace {

bool editDouble(const char* label, double& value, double min, double max, const char* format, bool logarithmic = false) {
    float v = static_cast<float>(value);
    const bool changed = ImGui::SliderFloat(label, &v, static_cast<float>(min), static_cast<float>(max), format,
                                            logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    if (changed) value = v;
    return changed;
}

void drawTracerSettings(TracerDesc& tracer) {
    int integrator = static_cast<int>(tracer.integrator);
    if (ImGui::Combo("integrator", &integrator, "Euler\0leapfrog\0RK4\0"))
        tracer.integrator = static_cast<TracerDesc::Integrator>(integrator);
    int policy = static_cast<int>(tracer.stepPolicy);
    if (ImGui::Combo("step policy", &policy, "uniform\0octree\0"))
        tracer.stepPolicy = static_cast<TracerDesc::StepPolicy>(policy);
    editDouble("step / min step (voxels)", tracer.stepVoxels, 0.05, 2.0, "%.3f", true);
    editDouble("epsilon", tracer.epsilon, 1e-4, 0.1, "%.4f", true);
    if (tracer.epsilonPrime < tracer.epsilon) tracer.epsilonPrime = tracer.epsilon;
    editDouble("epsilon'", tracer.epsilonPrime, tracer.epsilon, 0.2, "%.4f", true);
}

void drawMaterials(Scene& scene) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        Material& m = scene.objects[i].material;
        ImGui::Text("object %zu", i);
        editDouble("index", m.index, 1.0, 3.0, "%.3f");
        editDouble("extinction (grey)", m.extinction.g, 0.0, 50.0, "%.2f /m", true);
        m.extinction = Rgb(m.extinction.g);
        m.scattering = glm::min(m.scattering, m.extinction);
        ImGui::PopID();
    }
}

void drawSolver(SimDesc& sim) {
    int device = static_cast<int>(sim.device);  // SimDesc::Device: auto, cpu, gpu
    if (ImGui::Combo("device", &device, "auto\0cpu\0gpu\0")) sim.device = static_cast<SimDesc::Device>(device);
    editDouble("frame time (s)", sim.frameTime, 0.005, 0.2, "%.3f", true);
    editDouble("viscosity (m2/s)", sim.viscosity, 0.0, 1e-2, "%.2e", true);
    for (std::size_t i = 0; i < sim.sources.size(); ++i) {
        if (sim.sources[i].kind != SimDesc::Source::Kind::HotPlate) continue;
        ImGui::PushID(static_cast<int>(i));
        editDouble("hot plate (K)", sim.sources[i].temperature, 250.0, 900.0, "%.0f");
        ImGui::PopID();
    }
}

void drawFigures(const render::FrameResult& last, const ViewerStatus& status) {
    ImGui::Text("%.1f frames/s, %lld photons", status.framesPerSecond, status.photonsInUse);
    if (status.imageSpacePreview)
        ImGui::Text("preview: image space (raster refraction, caustic maps)");
    else if (last.imageSpace)
        ImGui::Text("image space (render.method)");
    else if (last.pixelStride > 1)
        ImGui::Text("preview: a ray per %d×%d pixels", last.pixelStride, last.pixelStride);
    else
        ImGui::Text("full image, %d rays a pixel averaged", last.viewSamples);
    if (status.simulated)
        ImGui::Text("simulated time %.3f s%s", status.simulatedTime,
                    status.simulationHeld ? " (held while the camera moves)" : "");
    if (!status.solverDevice.empty()) ImGui::Text("fluid solver on the %s", status.solverDevice == "gpu" ? "GPU" : "CPU");
    if (!status.waterDevice.empty()) ImGui::Text("water surface on the %s", status.waterDevice == "gpu" ? "GPU" : "CPU");
    for (const auto& stage : last.stages)
        ImGui::Text("%-15s %s %8.1f ms", stage.name.c_str(), stage.ran ? "ran " : "kept", stage.milliseconds);
    ImGui::Text("energy balance error %.2e", last.photons.balanceError());
    ImGui::Text("invariant drift max %.2e mean %.2e", last.photons.maxInvariantError, last.photons.meanInvariantError);
}

}  // namespace

PanelRequests ControlPanel::draw(const render::FrameResult& last, ViewerStatus& status, bool& paused, bool& pipelined,
                                 double& exposureEv, long long& photons) {
    PanelRequests requests;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin(status.sceneName.c_str());
    drawFigures(last, status);
    ImGui::Separator();
    editDouble("exposure (EV)", exposureEv, -8.0, 8.0, "%.1f");
    int count = static_cast<int>(photons);
    if (ImGui::SliderInt("photons", &count, 1024, 1 << 24, "%d", ImGuiSliderFlags_Logarithmic)) photons = count;
    if (status.simulated) {
        ImGui::Checkbox("paused (space)", &paused);
        ImGui::SameLine();
        requests.step = ImGui::Button("step (n)");
        ImGui::SameLine();
        requests.reset = ImGui::Button("reset (r)");
        // A solver on the GPU queues its passes on this context: nothing to pipeline.
        if (status.solverDevice != "gpu") ImGui::Checkbox("pipelined", &pipelined);
    }
    if (ImGui::CollapsingHeader("tracer")) drawTracerSettings(edited_.tracer);
    if (!edited_.objects.empty() && ImGui::CollapsingHeader("materials")) drawMaterials(edited_);
    if (edited_.sim && ImGui::CollapsingHeader("solver")) drawSolver(*edited_.sim);
    requests.apply = ImGui::Button("apply settings");
    ImGui::SameLine();
    requests.screenshot = ImGui::Button("screenshot (p)");
    if (!status.message.empty()) ImGui::TextWrapped("%s", status.message.c_str());
    ImGui::TextDisabled("left drag: orbit  middle: pan  wheel: zoom  right: move light");
    ImGui::End();
    return requests;
}

}  // namespace eikon::view
