// peer_case_bi4.cpp - the particle file (NAME.bi4) of DualSPHysics' 2D dam break case for the peer
// comparison of `make bench` (scripts/bench_peer.py), in place of DualSPHysics' closed case
// generator GenCase. It is compiled by scripts/bench_peer.py against the user's DualSPHysics
// source tree (its JPartDataBi4 writer and what that needs) into build/peer/; nothing of
// DualSPHysics is kept in this repository. scripts/bench_peer.py writes the case's NAME.xml.
//
// Lattice (GenCase's, as the case draws it): nodes at multiples of dp from the origin in the plane
// y = 0; the tank is one layer of boundary nodes on the bottom (z = 0, x = 0..tank_x) and on the
// left and right walls (x = 0 and x = tank_x, z = dp..tank_z); the fluid is the column's nodes
// (0, fluid_x] x (0, fluid_z], those on the walls being boundary nodes. Boundary particles first,
// ids in that order. Fluid density from the hydrostatic column through the Tait equation
// rho = rho0 (1 + rho0 g depth / b)^(1/gamma), depth below the top fluid node; boundary at rho0.
//
// Usage: peer_case_bi4 OUTDIR NAME dp fluid_x fluid_z tank_x tank_z rho0 gamma b h mass g
// Prints "particles NB NF" (boundary, fluid).
#include "JPartDataBi4.h"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

// Nodes of the lattice along a length [m] (the last index, counting from 0).
static int nodes_along(double length_m, double dp_m) { return int(std::floor(length_m / dp_m + 1e-6)); }

// Positions of the tank's boundary nodes: bottom, then the left wall, then the right wall.
static std::vector<tdouble3> tank_nodes(double dp, double tank_x, double tank_z) {
  const int nx = nodes_along(tank_x, dp), nz = nodes_along(tank_z, dp);
  std::vector<tdouble3> p;
  for (int i = 0; i <= nx; i++) p.push_back(TDouble3(i * dp, 0, 0));
  for (int k = 1; k <= nz; k++) p.push_back(TDouble3(0, 0, k * dp));
  for (int k = 1; k <= nz; k++) p.push_back(TDouble3(nx * dp, 0, k * dp));
  return p;
}

// Positions of the column's fluid nodes, row by row from the bottom.
static std::vector<tdouble3> column_nodes(double dp, double fluid_x, double fluid_z) {
  const int nx = nodes_along(fluid_x, dp), nz = nodes_along(fluid_z, dp);
  std::vector<tdouble3> p;
  for (int k = 1; k <= nz; k++)
    for (int i = 1; i <= nx; i++) p.push_back(TDouble3(i * dp, 0, k * dp));
  return p;
}

int main(int argc, char** argv) {
  if (argc != 14) {
    fprintf(stderr, "usage: %s OUTDIR NAME dp fluid_x fluid_z tank_x tank_z rho0 gamma b h mass g\n", argv[0]);
    return 1;
  }
  double v[11];
  for (int k = 0; k < 11; k++) v[k] = atof(argv[3 + k]);
  const double dp = v[0], rho0 = v[5], gamma = v[6], b = v[7], h = v[8], mass = v[9], g = v[10];
  const std::string dir = std::string(argv[1]) + "/", name = argv[2];
  std::vector<tdouble3> pos = tank_nodes(dp, v[3], v[4]);
  const unsigned nb = unsigned(pos.size());
  const std::vector<tdouble3> fluid = column_nodes(dp, v[1], v[2]);
  pos.insert(pos.end(), fluid.begin(), fluid.end());
  const unsigned np = unsigned(pos.size());
  const double top_m = fluid.empty() ? 0 : fluid.back().z;
  std::vector<unsigned> idp(np);
  std::vector<tfloat3> vel(np, TFloat3(0));
  std::vector<float> rho(np);
  tdouble3 lo = pos[0], hi = pos[0];
  for (unsigned p = 0; p < np; p++) {
    idp[p] = p;
    const double depth_m = p < nb ? 0 : top_m - pos[p].z;
    rho[p] = float(rho0 * std::pow(1 + rho0 * g * depth_m / b, 1 / gamma));
    lo = MinValues(lo, pos[p]);
    hi = MaxValues(hi, pos[p]);
  }
  JPartDataBi4 file;
  file.ConfigBasic(0, 1, "mpsph-bench", "mpsph peer_case_bi4", name, true, 0, dir);
  file.ConfigParticles(np, nb, 0, 0, np - nb, lo, hi);
  file.ConfigCtes(dp, h, b, rho0, gamma, mass, mass);
  file.ConfigSimPeri(PERI_None, TDouble3(0), TDouble3(0), TDouble3(0));
  file.AddPartInfo(0, 0, np, 0, 0, 0, lo, hi);
  file.AddPartData(np, idp.data(), pos.data(), vel.data(), rho.data());
  file.SaveFileCase(name);
  printf("particles %u %u\n", nb, np - nb);
  return 0;
}
