// Boost.Odeint peers for make bench (see bench_odeint.h). The right-hand sides are the same
// (ContDyn) as everywhere (model.h), with R' = R w^ or q' = 1/2 q (x) (0, w) for the attitude (none
// for w alone); the reduced problem's is q' = 1/2 q (x) (0, w(t)) with w(t) from reduced.h, as
// GSL's.
#include "bench_odeint.h"

extern "C" {
#include "quaternion.h"
}

#include <array>
// odeint's error steppers leave scratch members uninitialized until first use; GCC 12 flags the
// copy in make_controlled once the three state sizes are instantiated (a warning about Boost's
// code, not ours).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
#include <new>

namespace odeint = boost::numeric::odeint;

namespace
{

template <std::size_t N> struct rhs {
    const sus_model *m;
    void operator()(const std::array<double, N> &y, std::array<double, N> &f, double) const
    {
        sus_contdyn(m, y.data(), f.data());
        if constexpr (N == 11) {
            // R' = R w^ with w = (w1, w2, 0): (R w^)_ij = sum_k R_ik (w^)_kj.
            const double w0 = y[0], w1 = y[1];
            for (int i = 0; i < 3; i++) {
                const double *R = y.data() + 2 + 3 * i;
                double *F = f.data() + 2 + 3 * i;
                F[0] = -R[2] * w1;
                F[1] = R[2] * w0;
                F[2] = R[0] * w1 - R[1] * w0;
            }
        } else if constexpr (N == 6) {
            const double w[3] = {y[0], y[1], 0.0};
            double p[4];
            sus_quat_mul_pure(p, y.data() + 2, w);
            for (int i = 0; i < 4; i++)
                f[2 + i] = 0.5 * p[i];
        }
    }
};

struct reduced_rhs {
    const sus_exact_fast *r;
    void operator()(const std::array<double, 4> &q, std::array<double, 4> &f, double t) const
    {
        double w[3] = {0.0, 0.0, 0.0}, p[4];
        sus_exact_fast_omega(r, t, w);
        sus_quat_mul_pure(p, q.data(), w);
        for (int i = 0; i < 4; i++)
            f[i] = 0.5 * p[i];
    }
};

struct base {
    virtual ~base() = default;
    virtual long run(double T, double *y) = 0;
};

template <std::size_t N> struct rkf78 final : base {
    rhs<N> f;
    double tol;
    rkf78(const sus_model *m, double t) : f{m}, tol(t) {}
    long run(double T, double *y) override
    {
        std::array<double, N> s;
        for (std::size_t i = 0; i < N; i++)
            s[i] = y[i];
        auto st = odeint::make_controlled(tol, tol,
                                          odeint::runge_kutta_fehlberg78<std::array<double, N>>());
        const long n = (long)odeint::integrate_adaptive(st, f, s, 0.0, T, 1e-3);
        for (std::size_t i = 0; i < N; i++)
            y[i] = s[i];
        return n;
    }
};

struct rkf78_reduced final : base {
    reduced_rhs f;
    double tol, rel;
    rkf78_reduced(const sus_exact_fast *r, double t, double rl) : f{r}, tol(t), rel(rl) {}
    long run(double T, double *y) override
    {
        std::array<double, 4> s = {y[0], y[1], y[2], y[3]};
        auto st = odeint::make_controlled(tol, rel,
                                          odeint::runge_kutta_fehlberg78<std::array<double, 4>>());
        const long n = (long)odeint::integrate_adaptive(st, f, s, 0.0, T, 1e-3);
        for (std::size_t i = 0; i < 4; i++)
            y[i] = s[i];
        return n;
    }
};

template <std::size_t N> struct bs final : base {
    rhs<N> f;
    odeint::bulirsch_stoer<std::array<double, N>> st;
    bs(const sus_model *m, double t) : f{m}, st(t, t) {}
    long run(double T, double *y) override
    {
        std::array<double, N> s;
        for (std::size_t i = 0; i < N; i++)
            s[i] = y[i];
        st.reset();
        const long n = (long)odeint::integrate_adaptive(st, f, s, 0.0, T, 1e-3);
        for (std::size_t i = 0; i < N; i++)
            y[i] = s[i];
        return n;
    }
};

} // namespace

struct suslov_odeint {
    base *impl;
};

extern "C" suslov_odeint *suslov_odeint_open(int stepper, int dim, double tol, const sus_model *m)
{
    base *b = nullptr;
    if (stepper == SUSLOV_ODEINT_RKF78)
        b = dim == 11  ? static_cast<base *>(new (std::nothrow) rkf78<11>(m, tol))
            : dim == 6 ? static_cast<base *>(new (std::nothrow) rkf78<6>(m, tol))
                       : static_cast<base *>(new (std::nothrow) rkf78<2>(m, tol));
    else
        b = dim == 11  ? static_cast<base *>(new (std::nothrow) bs<11>(m, tol))
            : dim == 6 ? static_cast<base *>(new (std::nothrow) bs<6>(m, tol))
                       : static_cast<base *>(new (std::nothrow) bs<2>(m, tol));
    if (!b)
        return nullptr;
    suslov_odeint *o = new (std::nothrow) suslov_odeint{b};
    if (!o)
        delete b;
    return o;
}

extern "C" suslov_odeint *suslov_odeint_open_reduced(const sus_exact_fast *r, double tol,
                                                     double rel)
{
    base *b = new (std::nothrow) rkf78_reduced(r, tol, rel);
    if (!b)
        return nullptr;
    suslov_odeint *o = new (std::nothrow) suslov_odeint{b};
    if (!o)
        delete b;
    return o;
}

extern "C" long suslov_odeint_run(suslov_odeint *o, double T, double *y)
{
    return o->impl->run(T, y);
}

extern "C" void suslov_odeint_close(suslov_odeint *o)
{
    if (o) {
        delete o->impl;
        delete o;
    }
}
