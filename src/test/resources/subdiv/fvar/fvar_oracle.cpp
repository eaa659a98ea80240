// Writes Far's face-varying values (uvs + faceuvs) of an OBJ shape refined uniformly,
// with the FVar linear interpolation given on the command line (overriding tags), and the
// scheme (catmark, the default, loop or bilinear) as an optional fifth argument.
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
using namespace OpenSubdiv;
struct UV { double u, v; void Clear() { u = v = 0; } void AddWithWeight(UV const & s, double w) { u += w * s.u; v += w * s.v; } };
int main(int argc, char** argv) {
    if (argc < 5) { fprintf(stderr, "usage: obj level fvarMode out [catmark|loop|bilinear]\n"); return 1; }
    std::string schemeName = argc > 5 ? argv[5] : "catmark";
    Sdc::SchemeType scheme = schemeName == "loop" ? Sdc::SCHEME_LOOP : schemeName == "bilinear" ? Sdc::SCHEME_BILINEAR : Sdc::SCHEME_CATMARK;
    std::ifstream in(argv[1]); int level = atoi(argv[2]); int mode = atoi(argv[3]);
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
    opt.SetFVarLinearInterpolation((Sdc::Options::FVarLinearInterpolation) mode);
    Far::TopologyDescriptor d;
    d.numVertices = (int) pos.size() / 3; d.numFaces = (int) sizes.size(); d.numVertsPerFace = sizes.data(); d.vertIndicesPerFace = verts.data();
    d.numCreases = (int) creaseW.size(); d.creaseVertexIndexPairs = creaseV.data(); d.creaseWeights = creaseW.data();
    d.numCorners = (int) cornerW.size(); d.cornerVertexIndices = cornerV.data(); d.cornerWeights = cornerW.data();
    d.numHoles = (int) holes.size(); d.holeIndices = holes.data();
    Far::TopologyDescriptor::FVarChannel ch; ch.numValues = (int) uvs.size() / 2; ch.valueIndices = fuv.data();
    d.numFVarChannels = 1; d.fvarChannels = &ch;
    Far::TopologyRefiner* r = Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(d,
        Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(scheme, opt));
    if (!r) { fprintf(stderr, "create failed\n"); return 1; }
    Far::TopologyRefiner::UniformOptions uo(level); uo.fullTopologyInLastLevel = true; r->RefineUniform(uo);
    std::vector<UV> buf(r->GetNumFVarValuesTotal(0));
    for (int i = 0; i < ch.numValues; i++) { buf[i].u = uvs[2 * i]; buf[i].v = uvs[2 * i + 1]; }
    UV* src = buf.data();
    Far::PrimvarRefinerReal<double> pr(*r);
    for (int l = 1; l <= level; l++) { UV* dst = src + r->GetLevel(l - 1).GetNumFVarValues(0); pr.InterpolateFaceVarying(l, src, dst, 0); src = dst; }
    Far::TopologyLevel const& L = r->GetLevel(level);
    FILE* o = fopen(argv[4], "w");
    static const char* names[] = {"FVAR_LINEAR_NONE", "FVAR_LINEAR_CORNERS_ONLY", "FVAR_LINEAR_CORNERS_PLUS1", "FVAR_LINEAR_CORNERS_PLUS2", "FVAR_LINEAR_BOUNDARIES", "FVAR_LINEAR_ALL"};
    fprintf(o, "# Far 3.5.0 face-varying values: %s level %d, scheme %s, option FVarLinearInterpolation %s (other options and tags from the shape)\n", argv[1], level, schemeName.c_str(), names[mode]);
    fprintf(o, "uvs %d\n", L.GetNumFVarValues(0));
    for (int i = 0; i < L.GetNumFVarValues(0); i++) fprintf(o, "%.17g %.17g\n", src[i].u, src[i].v);
    fprintf(o, "faceuvs %d\n", L.GetNumFaces());
    for (int f = 0; f < L.GetNumFaces(); f++) {
        Far::ConstIndexArray fv = L.GetFaceFVarValues(f, 0);
        for (int k = 0; k < fv.size(); k++) fprintf(o, k ? " %d" : "%d", fv[k]);
        fprintf(o, "\n");
    }
    fprintf(o, "end 0\n"); fclose(o);
    return 0;
}
