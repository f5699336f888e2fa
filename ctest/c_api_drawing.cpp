// Drawings through the medax C API, as a CAM program reading a customer's
// DXF would: a part with a bore, a second part beside it, a centre line
// and a note, some on other layers. Checks the shapes (areas worked out
// here by hand), the ignored things with their layers and reasons, layer
// selection, a drawing with no closed profile (no shapes, not an error),
// the JSON written, and NULL and out-of-range arguments with the
// out-params left alone.

#include "test_support.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string temp_path(const std::string& name) {
    return (fs::temp_directory_path() / ("medax_ctest_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::string line(const char* layer, double x0, double y0, double x1, double y1) {
    return std::string("0\nLINE\n8\n") + layer + "\n10\n" + std::to_string(x0) + "\n20\n" + std::to_string(y0) +
           "\n11\n" + std::to_string(x1) + "\n21\n" + std::to_string(y1) + "\n";
}

std::string rect(const char* layer, double x0, double y0, double x1, double y1) {
    return line(layer, x0, y0, x1, y0) + line(layer, x1, y0, x1, y1) + line(layer, x1, y1, x0, y1) +
           line(layer, x0, y1, x0, y0);
}

// A 40 x 20 plate with a bore of radius 5 (layer PART), a 10 x 10 block
// beside it (layer PART), a centre line through the bore (layer CENTER)
// and a note (layer TEXT).
std::string drawing() {
    std::string s = "0\nSECTION\n2\nENTITIES\n";
    s += rect("PART", 0, 0, 40, 20);
    s += "0\nCIRCLE\n8\nPART\n10\n20\n20\n10\n40\n5\n";
    s += rect("PART", 50, 0, 60, 10);
    s += line("CENTER", 12, 10, 28, 10);
    s += "0\nTEXT\n8\nTEXT\n10\n0\n20\n25\n40\n2.5\n1\nPLATE\n";
    s += "0\nENDSEC\n0\nEOF\n";
    return s;
}

std::string write(const std::string& name, const std::string& text) {
    const std::string path = temp_path(name);
    std::ofstream(path) << text;
    return path;
}

double area_of(const mx_drawing* d, size_t k) {
    mx_shape2d* s = nullptr;
    MT_CHECK_OK(mx_drawing_shape(d, k, &s));
    double area = -1.0;
    MT_CHECK_OK(mx_shape2d_area(s, &area));
    mx_shape2d_free(s);
    return area;
}

void every_layer() {
    mt::begin_case("every layer");
    const std::string path = write("parts.dxf", drawing());
    mx_drawing* d = nullptr;
    MT_CHECK_OK(mx_drawing_from_file(path.c_str(), MX_FORMAT_AUTO, nullptr, nullptr, &d));
    size_t shapes = 0, ignored = 0;
    MT_CHECK_OK(mx_drawing_shape_count(d, &shapes));
    MT_CHECK_EQ(shapes, size_t{2});
    MT_CHECK_NEAR(area_of(d, 0), 800.0 - 25.0 * kPi, 1e-12);
    MT_CHECK_NEAR(area_of(d, 1), 100.0, 1e-12);
    MT_CHECK_OK(mx_drawing_ignored_count(d, &ignored));
    MT_CHECK_EQ(ignored, size_t{2});
    bool text = false, centre = false;
    for (size_t k = 0; k < ignored; ++k) {
        mx_ignored i{};
        MT_CHECK_OK(mx_drawing_get_ignored(d, k, &i));
        if (i.kind == MX_IGNORED_ENTITY) {
            text = std::strcmp(i.layer, "TEXT") == 0 && std::strncmp(i.reason, "TEXT", 4) == 0 && i.y == 25.0;
        }
        if (i.kind == MX_IGNORED_OPEN_CHAIN) {
            centre = std::strcmp(i.layer, "CENTER") == 0 && i.source > 0;
        }
    }
    MT_CHECK(text);
    MT_CHECK(centre);
    // Out of range: an error, the out-param left alone.
    mx_shape2d* none = reinterpret_cast<mx_shape2d*>(0x1);
    MT_CHECK_STATUS(mx_drawing_shape(d, 2, &none), MX_ERR_INDEX_OUT_OF_RANGE);
    MT_CHECK(none == reinterpret_cast<mx_shape2d*>(0x1));
    mx_ignored untouched{};
    untouched.source = 77;
    MT_CHECK_STATUS(mx_drawing_get_ignored(d, ignored, &untouched), MX_ERR_INDEX_OUT_OF_RANGE);
    MT_CHECK_EQ(untouched.source, size_t{77});
    // The JSON holds both shapes.
    const std::string json = temp_path("parts.json");
    MT_CHECK_OK(mx_drawing_write_json(d, json.c_str()));
    std::ifstream in(json);
    const std::string text_json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    MT_CHECK(text_json.find("\"shapes\": [{\"loops\"") != std::string::npos);
    MT_CHECK(text_json.find("\"open_chain\"") != std::string::npos);
    // A shape taken out outlives its drawing.
    mx_shape2d* kept = nullptr;
    MT_CHECK_OK(mx_drawing_shape(d, 1, &kept));
    mx_drawing_free(d);
    double area = 0.0;
    MT_CHECK_OK(mx_shape2d_area(kept, &area));
    MT_CHECK_NEAR(area, 100.0, 1e-12);
    mx_shape2d_free(kept);
    fs::remove(path);
    fs::remove(json);
}

void one_layer_and_no_profile() {
    mt::begin_case("layers");
    const std::string path = write("layers.dxf", drawing());
    const char* layers[] = {"CENTER"};
    mx_drawing_select select{};
    MT_CHECK_OK(mx_drawing_select_init(&select, sizeof select));
    select.layers = layers;
    select.layer_count = 1;
    mx_drawing* d = nullptr;
    // The centre line alone closes nothing: no shapes, and no error.
    MT_CHECK_OK(mx_drawing_from_file(path.c_str(), MX_FORMAT_DXF, nullptr, &select, &d));
    size_t shapes = 7;
    MT_CHECK_OK(mx_drawing_shape_count(d, &shapes));
    MT_CHECK_EQ(shapes, size_t{0});
    size_t ignored = 0;
    MT_CHECK_OK(mx_drawing_ignored_count(d, &ignored));
    MT_CHECK(ignored >= 2);  // the open chain, the layer PART left out
    mx_drawing_free(d);
    // NULL arguments.
    mx_drawing* untouched = reinterpret_cast<mx_drawing*>(0x1);
    MT_CHECK_STATUS(mx_drawing_from_file(nullptr, MX_FORMAT_AUTO, nullptr, nullptr, &untouched),
                    MX_ERR_NULL_ARGUMENT);
    mx_drawing_select missing{};
    MT_CHECK_OK(mx_drawing_select_init(&missing, sizeof missing));
    missing.layer_count = 2;
    MT_CHECK_STATUS(mx_drawing_from_file(path.c_str(), MX_FORMAT_AUTO, nullptr, &missing, &untouched),
                    MX_ERR_NULL_ARGUMENT);
    const int16_t no_colour[] = {0};
    mx_drawing_select bad_colour{};
    MT_CHECK_OK(mx_drawing_select_init(&bad_colour, sizeof bad_colour));
    bad_colour.colours = no_colour;
    bad_colour.colour_count = 1;
    MT_CHECK_STATUS(mx_drawing_from_file(path.c_str(), MX_FORMAT_AUTO, nullptr, &bad_colour, &untouched),
                    MX_ERR_INVALID_ARGUMENT);
    mx_drawing_select unset{};  // struct_size 0: not initialised
    MT_CHECK_STATUS(mx_drawing_from_file(path.c_str(), MX_FORMAT_AUTO, nullptr, &unset, &untouched),
                    MX_ERR_INVALID_ARGUMENT);
    MT_CHECK(untouched == reinterpret_cast<mx_drawing*>(0x1));
    MT_CHECK_STATUS(mx_drawing_shape_count(nullptr, &shapes), MX_ERR_NULL_ARGUMENT);
    MT_CHECK_STATUS(mx_drawing_from_file("/nonexistent/x.dxf", MX_FORMAT_AUTO, nullptr, nullptr, &untouched),
                    MX_ERR_IO);
    mx_drawing_free(nullptr);
    fs::remove(path);
}

// Two closed polylines sharing an edge (handles 2A and 2B, colour 1 and
// by layer on a layer of colour 3), a circle drawn twice (handles 3A, 3B):
// read from memory, selected by colour, the touching pair and the copy
// named by handle.
void memory_colours_and_handles() {
    mt::begin_case("memory, colours, handles");
    const std::string text =
        "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n0\nLAYER\n2\nGREEN\n62\n3\n0\nENDTAB\n0\nENDSEC\n"
        "0\nSECTION\n2\nENTITIES\n"
        "0\nLWPOLYLINE\n5\n2A\n8\n0\n62\n1\n90\n4\n70\n1\n10\n0\n20\n0\n10\n10\n20\n0\n10\n10\n20\n10\n10\n0\n20\n10\n"
        "0\nLWPOLYLINE\n5\n2B\n8\nGREEN\n90\n4\n70\n1\n10\n10\n20\n2\n10\n14\n20\n2\n10\n14\n20\n6\n10\n10\n20\n6\n"
        "0\nCIRCLE\n5\n3A\n8\n0\n10\n30\n20\n0\n40\n2\n"
        "0\nCIRCLE\n5\n3B\n8\n0\n10\n30\n20\n0\n40\n2\n"
        "0\nENDSEC\n0\nEOF\n";
    mx_drawing* d = nullptr;
    MT_CHECK_OK(mx_drawing_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), MX_FORMAT_AUTO,
                                       nullptr, nullptr, &d));
    size_t shapes = 0, warnings = 0, ignored = 0;
    MT_CHECK_OK(mx_drawing_shape_count(d, &shapes));
    MT_CHECK_EQ(shapes, size_t{3});
    MT_CHECK_OK(mx_drawing_warning_count(d, &warnings));
    MT_CHECK_EQ(warnings, size_t{1});
    mx_warning w{};
    MT_CHECK_OK(mx_drawing_get_warning(d, 0, &w));
    MT_CHECK(w.kind == MX_WARNING_TOUCHING_SHAPES);
    MT_CHECK(w.handles[0] + w.handles[1] == 0x2A + 0x2B && w.handles[0] != w.handles[1]);
    MT_CHECK(w.x == 10.0 && w.y >= 2.0 && w.y <= 6.0);
    MT_CHECK_STATUS(mx_drawing_get_warning(d, 1, &w), MX_ERR_INDEX_OUT_OF_RANGE);
    MT_CHECK_OK(mx_drawing_ignored_count(d, &ignored));
    MT_CHECK_EQ(ignored, size_t{1});
    mx_ignored copy{};
    MT_CHECK_OK(mx_drawing_get_ignored(d, 0, &copy));
    MT_CHECK(copy.kind == MX_IGNORED_DUPLICATE_LOOP);
    MT_CHECK_EQ(copy.handle, uint64_t{0x3B});
    MT_CHECK_EQ(copy.other_handle, uint64_t{0x3A});
    mx_drawing_free(d);
    // Green only: the square on layer GREEN, by layer.
    const int16_t green[] = {3};
    mx_drawing_select select{};
    MT_CHECK_OK(mx_drawing_select_init(&select, sizeof select));
    select.colours = green;
    select.colour_count = 1;
    MT_CHECK_OK(mx_drawing_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), MX_FORMAT_DXF,
                                       nullptr, &select, &d));
    MT_CHECK_OK(mx_drawing_shape_count(d, &shapes));
    MT_CHECK_EQ(shapes, size_t{1});
    MT_CHECK_NEAR(area_of(d, 0), 16.0, 1e-12);
    mx_drawing_free(d);
    // NULL data is fine only when empty: an empty drawing has no shapes.
    mx_drawing* untouched = reinterpret_cast<mx_drawing*>(0x1);
    MT_CHECK_STATUS(mx_drawing_from_memory(nullptr, 5, MX_FORMAT_DXF, nullptr, nullptr, &untouched),
                    MX_ERR_NULL_ARGUMENT);
    MT_CHECK(untouched == reinterpret_cast<mx_drawing*>(0x1));
}

}  // namespace

int main() {
    every_layer();
    one_layer_and_no_profile();
    memory_colours_and_handles();
    return mt::finish("c_api_drawing");
}
