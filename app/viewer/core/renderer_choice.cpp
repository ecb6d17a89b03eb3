#include "renderer_choice.hpp"

#include <array>

namespace facet::view {
namespace {

struct Entry {
    RendererChoice choice;
    std::string_view name;
    std::string_view label;
};

constexpr std::array kEntries{
    Entry{RendererChoice::Cpu, "cpu", "CPU engine"},
    Entry{RendererChoice::OpenGl, "gl", "OpenGL twin"},
    Entry{RendererChoice::Split, "split", "CPU | OpenGL side by side"},
    Entry{RendererChoice::Lab, "lab", "Your pipeline"},
    Entry{RendererChoice::LabSplit, "lab-split", "Compare your pipeline | facet"},
};

const Entry& entry(RendererChoice choice) {
    for (const Entry& e : kEntries)
        if (e.choice == choice) return e;
    return kEntries[0];
}

/// One line whatever the text holds.
std::string oneLine(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '\n')
            out += " | ";
        else if (c != '\r')
            out += c;
    }
    return out;
}

}  // namespace

std::vector<std::string_view> rendererNames() {
    std::vector<std::string_view> names;
    for (const Entry& e : kEntries) names.push_back(e.name);
    return names;
}

std::optional<RendererChoice> parseRenderer(std::string_view name) {
    for (const Entry& e : kEntries)
        if (e.name == name) return e.choice;
    return std::nullopt;
}

std::string_view toString(RendererChoice choice) {
    return entry(choice).name;
}

std::string_view rendererLabel(RendererChoice choice) {
    return entry(choice).label;
}

RendererChoice nextRenderer(RendererChoice choice) {
    switch (choice) {
        case RendererChoice::Cpu:
            return RendererChoice::OpenGl;
        case RendererChoice::OpenGl:
            return RendererChoice::Split;
        case RendererChoice::Split:
        case RendererChoice::Lab:
        case RendererChoice::LabSplit:
            break;
    }
    return RendererChoice::Cpu;
}

bool isLab(RendererChoice choice) {
    return choice == RendererChoice::Lab || choice == RendererChoice::LabSplit;
}

FramePlan planFrame(RendererChoice choice, bool compareEnabled) {
    FramePlan p;
    // The lab's pipeline is drawn in the twin's place: the same frame, divider and difference.
    p.engine = choice != RendererChoice::OpenGl && choice != RendererChoice::Lab;
    p.engineCompare = choice == RendererChoice::Cpu && compareEnabled;
    p.twin = choice != RendererChoice::Cpu;
    p.sideBySide = choice == RendererChoice::Split || choice == RendererChoice::LabSplit;
    return p;
}

void selectRenderer(RendererChoice& current, RendererChoice wanted, CompareSettings& compare) {
    current = wanted;
    if (wanted != RendererChoice::Cpu) compare.enabled = false;
}

void setCompare(bool on, RendererChoice& current, CompareSettings& compare) {
    compare.enabled = on;
    if (on) current = RendererChoice::Cpu;
}

std::string rendererLogText(const RendererLog& log) {
    std::string s;
    s += "engine_frames " + std::to_string(log.engineFrames) + "\n";
    s += "twin_frames " + std::to_string(log.twinFrames) + "\n";
    s += "renderer_switches " + std::to_string(log.switches) + "\n";
    s += "twin_device " + oneLine(log.device) + "\n";
    s += "twin_error " + oneLine(log.error) + "\n";
    return s;
}

}  // namespace facet::view
