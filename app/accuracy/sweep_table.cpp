#include "sweep_table.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace facet::app {

void SweepTable::add(std::vector<std::string> cells) {
    assert(cells.size() == columns.size());
    rows.push_back(std::move(cells));
}

std::string cell(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

std::vector<std::string> referenceDiffColumns() {
    return {"fast_covered",  "ref_covered",    "ambiguous",
            "coverage_diff", "max_color_diff", "nan_depth"};
}

std::vector<std::string> referenceDiffCells(const ReferenceDiff& d) {
    return {cell(static_cast<double>(d.fastCovered)),
            cell(static_cast<double>(d.refCovered)),
            cell(static_cast<double>(d.ambiguous)),
            cell(static_cast<double>(d.coverageDiffers)),
            cell(d.maxColorDiff),
            cell(static_cast<double>(d.nanDepth))};
}

Status writeSweepCsv(const std::string& path, const SweepTable& table,
                     const std::vector<std::string>& notes) {
    std::ofstream out(path);
    if (!out) return Error{{path, 0}, "cannot write the sweep's CSV"};
    for (const std::string& n : notes) out << "# " << n << '\n';
    auto line = [&out](const std::vector<std::string>& cells) {
        for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
        out << '\n';
    };
    line(table.columns);
    for (const auto& row : table.rows) line(row);
    out.flush();
    if (!out) return Error{{path, 0}, "writing the sweep's CSV failed"};
    return {};
}

}  // namespace facet::app
