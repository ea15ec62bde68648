// lap-eigen -- baseline for bench/b-laplacian.sh: Eigen's SimplicialLLT
// (AMD ordering) on the matrix lap-solve wrote; best of 3 runs, CPU seconds.
// Built by b-laplacian.sh itself (C++ stays out of the tools' build).
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <ctime>
#include <cstdio>
#include <cstdint>
#include <vector>

static double now()
{
    return (double)std::clock() / CLOCKS_PER_SEC;        // CPU time, like lap-solve
}

int main(int argc, char **argv)
{
    if (argc < 2) { std::fprintf(stderr, "usage: lap-eigen MATRIX\n"); return 2; }
    FILE *f = std::fopen(argv[1], "rb");
    if (!f) { std::perror(argv[1]); return 1; }
    int32_t n; int64_t nnz;
    if (std::fread(&n, 4, 1, f) != 1 || std::fread(&nnz, 8, 1, f) != 1) return 1;
    std::vector<Eigen::Triplet<double>> T;
    T.reserve(nnz);
    for (int64_t k = 0; k < nnz; k++) {
        int32_t i, j; double x;
        if (std::fread(&i, 4, 1, f) != 1 || std::fread(&j, 4, 1, f) != 1 || std::fread(&x, 8, 1, f) != 1)
            return 1;
        T.emplace_back(i, j, x);
    }
    Eigen::MatrixXd B(n, 3);
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            if (std::fread(&B(i, c), 8, 1, f) != 1) return 1;
    std::fclose(f);
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(T.begin(), T.end());          // upper triangle
    double bf = 1e9, bs = 1e9;
    Eigen::MatrixXd X;
    for (int rep = 0; rep < 3; rep++) {
        Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Upper> llt;
        double t0 = now();
        llt.compute(A);
        double t1 = now();
        if (llt.info() != Eigen::Success) { std::fprintf(stderr, "not SPD\n"); return 1; }
        X = llt.solve(B);
        double t2 = now();
        if (t1 - t0 < bf) bf = t1 - t0;
        if (t2 - t1 < bs) bs = t2 - t1;
    }
    Eigen::SparseMatrix<double> Af = A.selfadjointView<Eigen::Upper>();
    double res = (Af * X - B).norm() / B.norm();
    std::printf("factor %.6f\nsolve3 %.6f\nresidual %.3g\n", bf, bs, res);
    return 0;
}
