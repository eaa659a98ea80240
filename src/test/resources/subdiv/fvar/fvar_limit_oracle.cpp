// Writes OpenSubdiv Bfr's face-varying (UV) limit surface of an OBJ shape at pseudo-random
// parameters in its faces, under each of the six FVarLinearInterpolation modes: see README.md
// beside this file for the format.
// Usage: fvar_limit_oracle shape.obj [catmark|loop|bilinear] [maxFaces [skippedFace,...]]
// The topology is built exactly as fvar_oracle.cpp builds it (same tags, same Sdc options), then
// Bfr::RefinerSurfaceFactory<> with approximation levels 2 (smooth) and 6 (sharp).
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
using namespace OpenSubdiv;

// splitmix64, seeded from the file name: the parameters are written out, so only this program
// depends on it (for reproducible output).
static uint64_t state;
static uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
// An integer in [1, 1023]: parameters are multiples of 1/1024 (or 1/2048), exact in binary.
static int grid() { return 1 + (int) (next() % 1023); }

static const int MODES = 6;

int main(int argc, char** argv) {
    if (argc < 2) { fprintf(stderr, "usage: obj [catmark|loop|bilinear] [maxFaces [skippedFace,...]]\n"); return 1; }
    std::string schemeName = argc > 2 ? argv[2] : "catmark";
    int maxFaces = argc > 3 ? atoi(argv[3]) : 1 << 30;
    std::vector<int> skip;
    if (argc > 4) { std::istringstream ss(argv[4]); std::string t; while (std::getline(ss, t, ',')) skip.push_back(atoi(t.c_str())); }
    Sdc::SchemeType scheme = schemeName == "loop" ? Sdc::SCHEME_LOOP : schemeName == "bilinear" ? Sdc::SCHEME_BILINEAR : Sdc::SCHEME_CATMARK;
    std::ifstream in(argv[1]);
    std::vector<double> pos, uvs; std::vector<int> sizes, verts, fuv, creaseV, cornerV, holes; std::vector<float> creaseW, cornerW;
    Sdc::Options opt; opt.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ss(line); std::string k; ss >> k;
        if (k == "v") { double x, y, z; ss >> x >> y >> z; pos.push_back(x); pos.push_back(y); pos.push_back(z); }
        else if (k == "vt") { double a, b; ss >> a >> b; uvs.push_back(a); uvs.push_back(b); }
        else if (k == "f") { std::string c; int n = 0; while (ss >> c) { int vi = 0, ti = 0; sscanf(c.c_str(), "%d/%d", &vi, &ti); verts.push_back(vi - 1); fuv.push_back(ti - 1); n++; } sizes.push_back(n); }
        else if (k == "t") {
            std::string name, counts; ss >> name >> counts; int ni, nf, ns; sscanf(counts.c_str(), "%d/%d/%d", &ni, &nf, &ns);
            std::vector<int> iv(ni); std::vector<float> fv(nf); std::vector<std::string> sv(ns);
            for (auto& x : iv) ss >> x; for (auto& x : fv) ss >> x; for (auto& x : sv) ss >> x;
            if (name == "crease") for (int i = 0; i + 1 < ni; i += 2) { creaseV.push_back(iv[i]); creaseV.push_back(iv[i + 1]); creaseW.push_back(nf > 1 ? fv[i / 2] : fv[0]); }
            else if (name == "corner") for (int i = 0; i < ni; i++) { cornerV.push_back(iv[i]); cornerW.push_back(nf > 1 ? fv[i] : fv[0]); }
            else if (name == "hole") for (int i = 0; i < ni; i++) holes.push_back(iv[i]);
            else if (name == "interpolateboundary") opt.SetVtxBoundaryInterpolation(iv[0] == 0 ? Sdc::Options::VTX_BOUNDARY_NONE : iv[0] == 1 ? Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER : Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
            else if (name == "creasemethod") opt.SetCreasingMethod(sv[0] == "chaikin" ? Sdc::Options::CREASE_CHAIKIN : Sdc::Options::CREASE_UNIFORM);
            else if (name == "smoothtriangles") opt.SetTriangleSubdivision(sv[0] == "smooth" ? Sdc::Options::TRI_SUB_SMOOTH : Sdc::Options::TRI_SUB_CATMARK);
        }
    }
    Far::TopologyDescriptor d;
    d.numVertices = (int) pos.size() / 3; d.numFaces = (int) sizes.size(); d.numVertsPerFace = sizes.data(); d.vertIndicesPerFace = verts.data();
    d.numCreases = (int) creaseW.size(); d.creaseVertexIndexPairs = creaseV.data(); d.creaseWeights = creaseW.data();
    d.numCorners = (int) cornerW.size(); d.cornerVertexIndices = cornerV.data(); d.cornerWeights = cornerW.data();
    d.numHoles = (int) holes.size(); d.holeIndices = holes.data();
    Far::TopologyDescriptor::FVarChannel ch; ch.numValues = (int) uvs.size() / 2; ch.valueIndices = fuv.data();
    d.numFVarChannels = 1; d.fvarChannels = &ch;

    // One refiner and factory per mode: the mode is an Sdc option of the refiner.
    std::vector<Far::TopologyRefiner*> refiners;
    std::vector<Bfr::RefinerSurfaceFactory<>*> factories;
    Bfr::RefinerSurfaceFactory<>::Options so;
    so.SetApproxLevelSmooth(2).SetApproxLevelSharp(6);
    for (int m = 0; m < MODES; m++) {
        opt.SetFVarLinearInterpolation((Sdc::Options::FVarLinearInterpolation) m);
        Far::TopologyRefiner* r = Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(d,
            Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(scheme, opt));
        if (!r) { fprintf(stderr, "create failed\n"); return 1; }
        refiners.push_back(r);
        factories.push_back(new Bfr::RefinerSurfaceFactory<>(*r, so));
    }

    // The faces sampled: all of them, or maxFaces of them chosen at random (in index order).
    int nf = d.numFaces;
    std::string base = argv[1]; base = base.substr(base.find_last_of('/') + 1);
    state = 0; for (char c : base) state = state * 31 + (unsigned char) c;
    std::vector<int> faces(nf); for (int f = 0; f < nf; f++) faces[f] = f;
    if (nf > maxFaces) {
        for (int i = 0; i < maxFaces; i++) std::swap(faces[i], faces[i + (int) (next() % (uint64_t) (nf - i))]);
        faces.resize(maxFaces); std::sort(faces.begin(), faces.end());
    }

    std::string shape = base.substr(0, base.find('.'));
    std::vector<std::string> rows;
    Bfr::Surface<double> s;
    std::vector<double> patch;
    char buf[256];
    for (int f : faces) {
        if (std::find(skip.begin(), skip.end(), f) != skip.end()) continue;
        // The parameters depend only on the face's size and the scheme.
        Bfr::Parameterization p(scheme, sizes[f]);
        double uv[2];
        if (p.GetType() == Bfr::Parameterization::QUAD) { uv[0] = grid() / 1024.0; uv[1] = grid() / 1024.0; }
        else if (p.GetType() == Bfr::Parameterization::TRI) {
            int i, j; do { i = grid(); j = grid(); } while (i + j >= 1024);
            uv[0] = i / 1024.0; uv[1] = j / 1024.0;
        } else {
            int q = (int) (next() % (uint64_t) p.GetFaceSize());
            double sub[2] = {grid() / 2048.0, grid() / 2048.0};
            p.ConvertSubFaceToCoord(q, sub, uv);
        }
        std::string row;
        snprintf(buf, sizeof buf, "%d %.17g %.17g", f, uv[0], uv[1]);
        row = buf;
        std::string last;
        bool any = false;
        for (int m = 0; m < MODES; m++) {
            std::string val;
            if (!factories[m]->InitFaceVaryingSurface(f, &s, 0)) {
                val = "x";
            } else {
                patch.resize(2 * s.GetNumPatchPoints());
                s.PreparePatchPoints(uvs.data(), 2, patch.data(), 2);
                double out[2];
                s.Evaluate(uv, patch.data(), 2, out);
                snprintf(buf, sizeof buf, "%.10g %.10g", out[0], out[1]);
                val = buf;
                any = true;
            }
            // A mode giving the same (printed) value as the mode before it is written "=".
            row += " " + (m > 0 && val == last ? std::string("=") : val);
            last = val;
        }
        if (any) rows.push_back(row);
    }
    printf("shape %s %d\n", shape.c_str(), (int) rows.size());
    for (auto& x : rows) printf("%s\n", x.c_str());
    return 0;
}
