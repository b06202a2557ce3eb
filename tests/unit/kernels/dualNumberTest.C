/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Forward-mode dual numbers (dualNumber.H, sparseDual.H): the
    derivatives a dual<N> carries through arithmetic and the elementary
    functions are those of the calculus, exactly (to round-off) against
    closed forms, in several directions at once; a constant carries none.
    The sparse gradients of sparseDual are the dense ones, sorted by
    variable, also when they outgrow the inline buffer.
\*---------------------------------------------------------------------------*/
#include "dualNumber.H"
#include "sparseDual.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace form;

namespace
{

// A kernel written once for any scalar type: f(x, y) with every operation
// of dual (mixed with doubles on both sides)
template<class T>
T kernel(const T& x, const T& y)
{
    using std::sqrt; using std::exp; using std::abs; using std::max;
    using std::min;
    T a = 2.0*x*y - 3.0/(1.0 + x*x) + y/4.0 - (1.5 - x);
    a += sqrt(x*x + y*y + 1.0);
    a -= exp(0.3*y)/x;
    a *= abs(x - 2.0*y);
    a /= max(x, y) + min(x, T(0.5));
    return -a;
}

} // namespace


TEST(dual, derivativesOfAKernelAreExact)
{
    // f = -(g h)/(k), differentiated by hand:
    const auto exact = [](double x, double y, double& fx, double& fy)
    {
        const double r = std::sqrt(x*x + y*y + 1);
        const double g =
            2*x*y - 3/(1 + x*x) + y/4 - (1.5 - x) + r - std::exp(0.3*y)/x;
        const double gx =
            2*y + 6*x/((1 + x*x)*(1 + x*x)) + 1 + x/r + std::exp(0.3*y)/(x*x);
        const double gy = 2*x + 0.25 + y/r - 0.3*std::exp(0.3*y)/x;
        const double s = x - 2*y >= 0 ? 1 : -1;
        const double h = std::abs(x - 2*y), hx = s, hy = -2*s;
        const double k = std::max(x, y) + std::min(x, 0.5);
        const double kx = (x >= y ? 1 : 0) + (x <= 0.5 ? 1 : 0);
        const double ky = x >= y ? 0 : 1;
        const double f = -g*h/k;
        fx = -(gx*h + g*hx)/k - f*kx/k;
        fy = -(gy*h + g*hy)/k - f*ky/k;
        return f;
    };
    int n = 0;
    for (const double x : {0.3, 0.7, 1.9, 3.1})
    {
        for (const double y : {-1.2, 0.2, 1.1, 2.5})
        {
            double fx, fy;
            const double f = exact(x, y, fx, fy);
            // two directions at once: d/dx and d/dy
            const dual<2> X = dual<2>::seed(x, 0), Y = dual<2>::seed(y, 1);
            const dual<2> F = kernel(X, Y);
            EXPECT_NEAR(F.v, kernel(x, y), 1e-14*std::abs(f));
            EXPECT_NEAR(F.v, f, 1e-13*std::abs(f));
            EXPECT_NEAR(F.d[0], fx, 1e-12*(1 + std::abs(fx))) << x << ' ' << y;
            EXPECT_NEAR(F.d[1], fy, 1e-12*(1 + std::abs(fy))) << x << ' ' << y;
            // one direction: the directional derivative along (0.6, -0.8)
            dual<1> Xs(x), Ys(y);
            Xs.d[0] = 0.6;
            Ys.d[0] = -0.8;
            EXPECT_NEAR(kernel(Xs, Ys).d[0], 0.6*fx - 0.8*fy,
                        1e-12*(1 + std::abs(fx) + std::abs(fy)));
            ++n;
        }
    }
    EXPECT_EQ(n, 16);
    // a constant has no derivative
    const dual<3> c = kernel(dual<3>(0.7), dual<3>(1.1));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(c.d[k], 0.0);
}


TEST(sparseDual, gradientsAreThoseOfTheDenseDual)
{
    // the kernel's gradient with x and y as variables 3 and 7
    for (const double x : {0.3, 1.9})
    {
        for (const double y : {-1.2, 2.5})
        {
            const dual<2> F = kernel(dual<2>::seed(x, 0), dual<2>::seed(y, 1));
            const sparseDual S =
                kernel(sparseDual::variable(x, 3), sparseDual::variable(y, 7));
            EXPECT_NEAR(S.v, F.v, 1e-15*std::abs(F.v));
            ASSERT_EQ(S.size(), 2);
            EXPECT_EQ(S.index(0), 3);
            EXPECT_EQ(S.index(1), 7);
            EXPECT_NEAR(S.derivative(0), F.d[0], 1e-14*(1 + std::abs(F.d[0])));
            EXPECT_NEAR(S.derivative(1), F.d[1], 1e-14*(1 + std::abs(F.d[1])));
        }
    }
    // a constant has no gradient
    EXPECT_EQ(kernel(sparseDual(0.7), sparseDual(1.1)).size(), 0);
}


TEST(sparseDual, manyVariablesGrowOntoTheHeapAndStaySorted)
{
    // f = sum_k c_k x_k^2 + (sum_k x_k)^2 / 2 over 40 variables added in
    // a scrambled order: df/dx_k = 2 c_k x_k + sum_j x_j
    const int n = 40;
    std::vector<double> xv(n), c(n);
    for (int k = 0; k < n; ++k)
    {
        xv[k] = 0.1*k - 1.3;
        c[k] = 1 + 0.05*k;
    }
    sparseDual f(0.0), s(0.0);
    for (int j = 0; j < n; ++j)
    {
        const int k = (17*j) % n;      // every variable once, scrambled
        const sparseDual xk = sparseDual::variable(xv[k], k);
        f += c[k]*xk*xk;
        s = s + xk;
    }
    f += 0.5*s*s;
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += xv[k];
    ASSERT_EQ(f.size(), n);
    for (int j = 0; j < n; ++j)
    {
        EXPECT_EQ(f.index(j), j);
        EXPECT_NEAR(f.derivative(j), 2*c[j]*xv[j] + sum, 1e-13);
    }
    // copies and moves keep the gradient
    sparseDual g(f), h;
    h = std::move(g);
    EXPECT_EQ(h.size(), n);
    EXPECT_NEAR(h.derivative(n - 1), f.derivative(n - 1), 0.0);
    // add(): in order, repeated and out of order
    sparseDual a(1.0);
    a.add(2, 1.0).add(5, 2.0).add(5, 1.0).add(3, 4.0);
    ASSERT_EQ(a.size(), 3);
    EXPECT_EQ(a.index(1), 3);
    EXPECT_EQ(a.derivative(2), 3.0);
}
