// Wavefront OBJ loading through tinyobjloader (Debian libtinyobjloader-dev) into a Mesh with its BVH.
#include "Physics/Geometry/ObjLoader.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

namespace {

bool Fail(std::string* error, const std::string& path, const std::string& problem) {
    if (error != nullptr) *error = "OBJ file '" + path + "': " + problem;
    return false;
}

/// tinyobjloader messages end in newlines and may hold several lines; keep them on one line.
std::string OneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

/// Checks the file before tinyobjloader reads it: it opens, it is not a directory, and every face has at least 3
/// vertices (tinyobjloader silently drops shorter faces). False with *error set otherwise.
bool PrecheckObj(const std::string& path, std::string* error) {
    std::ifstream probe(path, std::ios::in | std::ios::binary);
    if (!probe) return Fail(error, path, std::string("cannot open: ") + std::strerror(errno));
    std::string line;
    int lineNumber = 0;
    while (std::getline(probe, line)) {
        ++lineNumber;
        std::istringstream tokens(line);
        std::string keyword, vertex;
        if (!(tokens >> keyword) || keyword != "f") continue;
        int count = 0;
        while (tokens >> vertex) ++count;
        if (count < 3) {
            std::ostringstream s;
            s << "malformed: line " << lineNumber << " is a face with " << count << " vertices (at least 3)";
            return Fail(error, path, s.str());
        }
    }
    if (probe.bad() || lineNumber == 0) {
        probe.clear();
        probe.seekg(0);
        char c;
        if (!probe.get(c) && !probe.eof()) return Fail(error, path, "cannot read (is it a directory?)");
    }
    return true;
}

}  // namespace

/// Loads every face of `path` (triangulated) into out->triangles and builds the BVH. Returns false with
/// *error naming the file and the problem (cannot open, parse error, invalid or out-of-range vertex index,
/// non-finite coordinate, face with fewer than 3 vertices, no faces); *out is left untouched on failure.
bool LoadMesh(const std::string& path, Mesh* out, std::string* error) {
    if (out == nullptr) return Fail(error, path, "no output mesh given");
    if (!PrecheckObj(path, error)) return false;

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        const std::string why = OneLine(reader.Error());
        return Fail(error, path, "parse error: " + (why.empty() ? std::string("unknown") : why));
    }
    // tinyobjloader skips (with only a warning) faces whose indices it cannot use; treat that as malformed.
    const std::string warning = OneLine(reader.Warning());
    if (warning.find("invalid") != std::string::npos || warning.find("Invalid") != std::string::npos)
        return Fail(error, path, "malformed: " + warning);

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const int vertexCount = static_cast<int>(attrib.vertices.size() / 3);
    for (float value : attrib.vertices)
        if (!std::isfinite(value)) return Fail(error, path, "malformed: a vertex coordinate is not finite");

    Mesh mesh;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const tinyobj::mesh_t& m = shape.mesh;
        size_t offset = 0;
        for (size_t f = 0; f < m.num_face_vertices.size(); ++f) {
            const int n = m.num_face_vertices[f];
            if (n != 3) {
                std::ostringstream s;
                s << "malformed: face " << f + 1 << " of shape '" << shape.name << "' has " << n
                  << " vertices after triangulation (expected 3)";
                return Fail(error, path, s.str());
            }
            Triangle tri;
            for (int k = 0; k < 3; ++k) {
                const int vi = m.indices[offset + k].vertex_index;
                if (vi < 0 || vi >= vertexCount) {
                    std::ostringstream s;
                    s << "malformed: face " << f + 1 << " of shape '" << shape.name << "' uses vertex " << vi + 1
                      << " but the file defines " << vertexCount << " vertices";
                    return Fail(error, path, s.str());
                }
                tri[k] = vec3(attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]);
            }
            mesh.triangles.push_back(tri);
            offset += static_cast<size_t>(n);
        }
    }
    if (mesh.triangles.empty()) return Fail(error, path, "no faces (a mesh needs at least one triangle)");

    AccelerateMesh(mesh);
    *out = std::move(mesh);
    if (error != nullptr) error->clear();
    return true;
}
