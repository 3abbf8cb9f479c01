// The C++ side of python/bench/bench_python.py: a law evaluated over a table of contacts in a
// plain loop, the cost the Python module's vectorised call is compared with.
//
//   batch_loop LAW FILE REPEATS
//
// FILE holds n contacts as raw float64 in the order U, Omega, a, b, psi, N, k (7 n numbers, as
// numpy's tofile() writes a (n, 7) C-order array). Prints the best wall time of REPEATS loops
// over the n contacts, in seconds, and a checksum of the outputs (so the loop is not optimised
// away, and the Python side can see that both evaluated the same thing).

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "friction/registry.h"

int main(int argc, char** argv) {
  try {
    if (argc != 4) throw std::invalid_argument("usage: batch_loop LAW FILE REPEATS");
    const auto law = frictionlab::friction::make_law(argv[1]);
    std::ifstream in(argv[2], std::ios::binary);
    std::vector<double> raw;
    double x = 0.0;
    while (in.read(reinterpret_cast<char*>(&x), sizeof x)) raw.push_back(x);
    if (raw.empty() || raw.size() % 7 != 0) throw std::invalid_argument(std::string(argv[2]) + ": not n x 7 float64");
    const std::size_t n = raw.size() / 7;
    std::vector<frictionlab::friction::ContactInput> contacts(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double* r = &raw[7 * i];
      contacts[i] = {r[0], r[1], r[2], r[3], r[4], r[5], r[6]};
    }
    std::vector<double> F1(n), F2(n), M(n);
    double best = 1e300;
    for (int rep = 0; rep < std::stoi(argv[3]); ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < n; ++i) {
        const auto f = law->evaluate(contacts[i]);
        F1[i] = f.F1;
        F2[i] = f.F2;
        M[i] = f.M;
      }
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += F1[i] + F2[i] + M[i];
    std::printf("%.9g %.17g\n", best, sum);
  } catch (const std::exception& e) {
    std::cerr << "batch_loop: error: " << e.what() << '\n';
    return 1;
  }
}
