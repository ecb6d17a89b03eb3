#pragma once
// Large meshes written by the tests themselves (not stored): loading them takes long enough to
// watch a progress bar and to cancel in the middle.

#include <cstdio>
#include <string>

namespace facet::test {

// An n × n grid as OBJ text with v, vt and vn on every corner (so every phase of the OBJ loader
// has work), quads split into two triangles: 2n² triangles, about 70 bytes per triangle.
inline std::string gridObj(int n) {
    std::string s = "# a grid written by a test\n";
    char line[160];
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) {
            std::snprintf(line, sizeof line, "v %g %g %g\nvt %g %g\n", x / double(n), y / double(n),
                          0.01 * ((x * 7 + y * 3) % 5), x / double(n), y / double(n));
            s += line;
        }
    s += "vn 0 0 1\n";
    const auto id = [n](int x, int y) { return y * (n + 1) + x + 1; };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int a = id(x, y), b = id(x + 1, y), c = id(x + 1, y + 1), d = id(x, y + 1);
            std::snprintf(line, sizeof line,
                          "f %d/%d/1 %d/%d/1 %d/%d/1\nf %d/%d/1 %d/%d/1 %d/%d/1\n", a, a, b, b, c,
                          c, a, a, c, c, d, d);
            s += line;
        }
    return s;
}

}  // namespace facet::test
