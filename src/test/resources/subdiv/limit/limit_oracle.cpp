// Writes OpenSubdiv Bfr's limit surface (position and first derivatives) of an OBJ shape at
// pseudo-random parameters in its faces: see README.md beside this file for the format.
// Usage: limit_oracle shape.obj out.txt [catmark|loop|bilinear] [approxSmooth approxSharp [skippedFace,...|- [irregularFaces]]]
// With irregularFaces > 0, only that many irregular faces (Bfr's IsRegular false) are sampled, at
// three points each: one anywhere, one near a random corner, one very near it (see README.md).
// The topology is built exactly as fvar_oracle.cpp builds it (same tags, same Sdc options).
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
using namespace OpenSubdiv;

// splitmix64: the parameters are written to the file, so nothing depends on this generator
// outside this program; it only makes the output reproducible.
static uint64_t state;
static uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
// An integer in [1, 1023]: parameters are multiples of 1/1024 (or 1/2048), exact in binary.
static int grid() { return 1 + (int) (next() % 1023); }

static const int POINTS_PER_FACE = 2;
static const int MAX_FACES = 48;

int main(int argc, char** argv) {
    if (argc < 3) { fprintf(stderr, "usage: obj out [catmark|loop|bilinear] [approxSmooth approxSharp]\n"); return 1; }
    std::string schemeName = argc > 3 ? argv[3] : "catmark";
    int approxSmooth = argc > 5 ? atoi(argv[4]) : 2, approxSharp = argc > 5 ? atoi(argv[5]) : 6;
    // Faces left out (written as "skipped", paramType -2): where this OpenSubdiv crashes.
    std::vector<int> skip;
    int irregularFaces = argc > 7 ? atoi(argv[7]) : 0;
    if (argc > 6 && std::string(argv[6]) != "-") { std::istringstream ss(argv[6]); std::string t; while (std::getline(ss, t, ',')) skip.push_back(atoi(t.c_str())); }
    Sdc::SchemeType scheme = schemeName == "loop" ? Sdc::SCHEME_LOOP : schemeName == "bilinear" ? Sdc::SCHEME_BILINEAR : Sdc::SCHEME_CATMARK;
    std::ifstream in(argv[1]);
    std::vector<double> pos; std::vector<int> sizes, verts, creaseV, cornerV, holes; std::vector<float> creaseW, cornerW;
    Sdc::Options opt; opt.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ss(line); std::string k; ss >> k;
        if (k == "v") { double x, y, z; ss >> x >> y >> z; pos.push_back(x); pos.push_back(y); pos.push_back(z); }
        else if (k == "f") { std::string c; int n = 0; while (ss >> c) { int vi = 0; sscanf(c.c_str(), "%d", &vi); verts.push_back(vi - 1); n++; } sizes.push_back(n); }
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
    Far::TopologyRefiner* r = Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(d,
        Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(scheme, opt));
    if (!r) { fprintf(stderr, "create failed\n"); return 1; }

    Bfr::RefinerSurfaceFactory<>::Options so;
    so.SetApproxLevelSmooth(approxSmooth).SetApproxLevelSharp(approxSharp);
    Bfr::RefinerSurfaceFactory<> factory(*r, so);

    // The faces sampled: all of them, or MAX_FACES of them chosen at random (in index order).
    int nf = d.numFaces;
    std::string base = argv[1]; base = base.substr(base.find_last_of('/') + 1);
    state = 0; for (char c : base) state = state * 31 + (unsigned char) c;
    std::vector<int> faces(nf); for (int f = 0; f < nf; f++) faces[f] = f;
    if (irregularFaces > 0) {
        // Only irregular faces with a limit surface: the approximation levels change nothing else.
        std::vector<int> irregular;
        Bfr::Surface<double> probe;
        for (int f = 0; f < nf; f++) {
            if (std::find(skip.begin(), skip.end(), f) != skip.end()) continue;
            if (factory.InitVertexSurface(f, &probe) && !probe.IsRegular()) irregular.push_back(f);
        }
        faces = irregular;
        int m = (int) faces.size();
        if (m > irregularFaces) {
            for (int i = 0; i < irregularFaces; i++) std::swap(faces[i], faces[i + (int) (next() % (uint64_t) (m - i))]);
            faces.resize(irregularFaces); std::sort(faces.begin(), faces.end());
        }
    } else if (nf > MAX_FACES) {
        for (int i = 0; i < MAX_FACES; i++) std::swap(faces[i], faces[i + (int) (next() % (uint64_t) (nf - i))]);
        faces.resize(MAX_FACES); std::sort(faces.begin(), faces.end());
    }

    FILE* o = fopen(argv[2], "w");
    fprintf(o, "# OpenSubdiv %d.%d.%d Bfr::Surface<double> limit of %s, scheme %s, approxLevelSmooth %d, approxLevelSharp %d\n",
        OPENSUBDIV_VERSION_MAJOR, OPENSUBDIV_VERSION_MINOR, OPENSUBDIV_VERSION_PATCH, base.c_str(), schemeName.c_str(), approxSmooth, approxSharp);
    fprintf(o, "# faces: face valid regular linear paramType numControlPoints; points: face u v P(3) Du(3) Dv(3)\n");
    fprintf(o, "options 1\n%d %d\n", approxSmooth, approxSharp);
    Bfr::Surface<double> s;
    std::vector<double> patch;
    std::vector<std::string> faceRows, pointRows;
    char buf[1024];
    for (int f : faces) {
        if (std::find(skip.begin(), skip.end(), f) != skip.end()) { snprintf(buf, sizeof buf, "%d 0 0 0 -2 0", f); faceRows.push_back(buf); continue; }
        bool valid = factory.InitVertexSurface(f, &s);
        if (!valid) { snprintf(buf, sizeof buf, "%d 0 0 0 -1 0", f); faceRows.push_back(buf); continue; }
        Bfr::Parameterization p = s.GetParameterization();
        snprintf(buf, sizeof buf, "%d 1 %d %d %d %d", f, (int) s.IsRegular(), (int) s.IsLinear(), (int) p.GetType(), s.GetNumControlPoints());
        faceRows.push_back(buf);
        patch.resize(3 * s.GetNumPatchPoints());
        s.PreparePatchPoints(pos.data(), 3, patch.data(), 3);
        int pointsPerFace = irregularFaces > 0 ? 3 : POINTS_PER_FACE;
        int corner = 0, q = 0;
        for (int k = 0; k < pointsPerFace; k++) {
            double uv[2];
            if (irregularFaces > 0) {
                // Point 0 anywhere; 1 within 1/32 of a random corner, 2 within 1/512 of it (deep
                // in the adaptive refinement, where the approximation levels matter). Sub-faces:
                // their corner 0 (the face's corner) or 2 (the face's centre).
                int span = k == 0 ? 1023 : k == 1 ? 32 : 2;
                if (k == 1) corner = (int) (next() % (uint64_t) (p.GetType() == Bfr::Parameterization::TRI ? 3 : 4));
                int i = 1 + (int) (next() % (uint64_t) span), j = 1 + (int) (next() % (uint64_t) span);
                double a = i / 1024.0, b = j / 1024.0;
                if (p.GetType() == Bfr::Parameterization::QUAD) {
                    if (k == 0) { uv[0] = a; uv[1] = b; }
                    else { uv[0] = corner == 1 || corner == 2 ? 1 - a : a; uv[1] = corner >= 2 ? 1 - b : b; }
                } else if (p.GetType() == Bfr::Parameterization::TRI) {
                    if (k == 0) { while (i + j >= 1024) { i = grid(); j = grid(); } uv[0] = i / 1024.0; uv[1] = j / 1024.0; }
                    else if (corner == 0) { uv[0] = a; uv[1] = b; }
                    else if (corner == 1) { uv[0] = 1 - a - b; uv[1] = b; }
                    else { uv[0] = a; uv[1] = 1 - a - b; }
                } else {
                    if (k < 2) q = (int) (next() % (uint64_t) p.GetFaceSize()); // point 2 near point 1
                    double sub[2] = {a, b};
                    if (k > 0 && corner >= 2) { sub[0] = 1 - a; sub[1] = 1 - b; }
                    p.ConvertNormalizedSubFaceToCoord(q, sub, uv);
                }
            } else if (p.GetType() == Bfr::Parameterization::QUAD) { uv[0] = grid() / 1024.0; uv[1] = grid() / 1024.0; }
            else if (p.GetType() == Bfr::Parameterization::TRI) {
                int i, j; do { i = grid(); j = grid(); } while (i + j >= 1024);
                uv[0] = i / 1024.0; uv[1] = j / 1024.0;
            } else {
                // Sub-face q (of the face's N) is the square [q % uDim, + 1/2] x [q / uDim, + 1/2].
                int q = (int) (next() % (uint64_t) p.GetFaceSize());
                double sub[2] = {grid() / 2048.0, grid() / 2048.0};
                p.ConvertSubFaceToCoord(q, sub, uv);
            }
            double P[3], Du[3], Dv[3];
            s.Evaluate(uv, patch.data(), 3, P, Du, Dv);
            snprintf(buf, sizeof buf, "%d %.17g %.17g %.13g %.13g %.13g %.13g %.13g %.13g %.13g %.13g %.13g",
                f, uv[0], uv[1], P[0], P[1], P[2], Du[0], Du[1], Du[2], Dv[0], Dv[1], Dv[2]);
            pointRows.push_back(buf);
        }
    }
    fprintf(o, "faces %d\n", (int) faceRows.size()); for (auto& x : faceRows) fprintf(o, "%s\n", x.c_str());
    fprintf(o, "points %d\n", (int) pointRows.size()); for (auto& x : pointRows) fprintf(o, "%s\n", x.c_str());
    fprintf(o, "end 0\n"); fclose(o);
    return 0;
}
