// The competitor of issue 7's third benchmark, written for camlray's bench:
// a single-threaded path tracer with the design of "Ray Tracing in One
// Weekend" (book 1) -- a flat list of spheres behind a virtual hit test (no
// BVH), materials behind a virtual scatter, doubles throughout, random
// numbers from the C library's rand() -- rendering the book's final scene.
// bench/whole builds it with g++ -O3 and times it in the same run as
// camlray, so that the samples-per-second ratio does not depend on how
// busy the shared machine is that day.
//
// Usage: rtiow WIDTH HEIGHT SPP DEPTH > image.ppm
// Prints "spheres N" and "seconds T" (the render, without writing) on stderr.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace {

double uniform() { return std::rand() / (RAND_MAX + 1.0); }
double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

struct V {
  double x, y, z;
  V() : x(0), y(0), z(0) {}
  V(double a, double b, double c) : x(a), y(b), z(c) {}
  V operator-() const { return {-x, -y, -z}; }
  V &operator+=(const V &o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  double norm2() const { return x * x + y * y + z * z; }
  double norm() const { return std::sqrt(norm2()); }
};

V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(V a, V b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
V operator/(V a, double s) { return (1.0 / s) * a; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V unit(V a) { return a / a.norm(); }

V random_v(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }

// uniform on the unit sphere, by rejection from the cube
V on_unit_sphere() {
  for (;;) {
    V p = random_v(-1, 1);
    double n2 = p.norm2();
    if (n2 > 1e-160 && n2 <= 1) return p / std::sqrt(n2);
  }
}

V in_unit_disk() {
  for (;;) {
    V p(uniform(-1, 1), uniform(-1, 1), 0);
    if (p.norm2() < 1) return p;
  }
}

V mirror(V d, V n) { return d - 2 * dot(d, n) * n; }

// Snell's law for a unit direction d against the unit normal n it meets
V bend(V d, V n, double eta) {
  double c = std::fmin(dot(-d, n), 1.0);
  V perp = eta * (d + c * n);
  V para = -std::sqrt(std::fabs(1.0 - perp.norm2())) * n;
  return perp + para;
}

struct Ray {
  V o, d;
};

class Material;

struct Hit {
  V p, n;
  double t;
  bool outside;
  const Material *m;
};

class Material {
 public:
  virtual ~Material() = default;
  virtual bool scatter(const Ray &in, const Hit &h, V &att, Ray &out) const = 0;
};

class Diffuse : public Material {
  V albedo;

 public:
  explicit Diffuse(V a) : albedo(a) {}
  bool scatter(const Ray &, const Hit &h, V &att, Ray &out) const override {
    V d = h.n + on_unit_sphere();
    if (std::fabs(d.x) < 1e-8 && std::fabs(d.y) < 1e-8 && std::fabs(d.z) < 1e-8) d = h.n;
    out = {h.p, d};
    att = albedo;
    return true;
  }
};

class Metal : public Material {
  V albedo;
  double fuzz;

 public:
  Metal(V a, double f) : albedo(a), fuzz(f < 1 ? f : 1) {}
  bool scatter(const Ray &in, const Hit &h, V &att, Ray &out) const override {
    V r = unit(mirror(in.d, h.n)) + fuzz * on_unit_sphere();
    out = {h.p, r};
    att = albedo;
    return dot(r, h.n) > 0;
  }
};

class Glass : public Material {
  double ior;

  static double schlick(double c, double eta) {
    double r0 = (1 - eta) / (1 + eta);
    r0 = r0 * r0;
    return r0 + (1 - r0) * std::pow(1 - c, 5);
  }

 public:
  explicit Glass(double i) : ior(i) {}
  bool scatter(const Ray &in, const Hit &h, V &att, Ray &out) const override {
    att = V(1, 1, 1);
    double eta = h.outside ? 1.0 / ior : ior;
    V d = unit(in.d);
    double c = std::fmin(dot(-d, h.n), 1.0);
    double s = std::sqrt(1.0 - c * c);
    V next = (eta * s > 1.0 || schlick(c, eta) > uniform()) ? mirror(d, h.n) : bend(d, h.n, eta);
    out = {h.p, next};
    return true;
  }
};

class Shape {
 public:
  virtual ~Shape() = default;
  virtual bool hit(const Ray &r, double tmin, double tmax, Hit &h) const = 0;
};

class Sphere : public Shape {
  V c;
  double rad;
  std::shared_ptr<Material> mat;

 public:
  Sphere(V centre, double radius, std::shared_ptr<Material> m) : c(centre), rad(radius), mat(std::move(m)) {}
  bool hit(const Ray &r, double tmin, double tmax, Hit &h) const override {
    V oc = c - r.o;
    double a = r.d.norm2();
    double hb = dot(r.d, oc);
    double disc = hb * hb - a * (oc.norm2() - rad * rad);
    if (disc < 0) return false;
    double sq = std::sqrt(disc);
    double t = (hb - sq) / a;
    if (t <= tmin || t >= tmax) {
      t = (hb + sq) / a;
      if (t <= tmin || t >= tmax) return false;
    }
    h.t = t;
    h.p = r.o + t * r.d;
    V n = (h.p - c) / rad;
    h.outside = dot(r.d, n) < 0;
    h.n = h.outside ? n : -n;
    h.m = mat.get();
    return true;
  }
};

class Group : public Shape {
 public:
  std::vector<std::shared_ptr<Shape>> items;
  bool hit(const Ray &r, double tmin, double tmax, Hit &h) const override {
    Hit tmp;
    bool any = false;
    double best = tmax;
    for (const auto &s : items)
      if (s->hit(r, tmin, best, tmp)) {
        any = true;
        best = tmp.t;
        h = tmp;
      }
    return any;
  }
};

V radiance(const Ray &r, int depth, const Shape &world) {
  if (depth <= 0) return V();
  Hit h;
  if (world.hit(r, 0.001, INFINITY, h)) {
    Ray next;
    V att;
    if (h.m->scatter(r, h, att, next)) return att * radiance(next, depth - 1, world);
    return V();
  }
  double a = 0.5 * (unit(r.d).y + 1.0);
  return (1.0 - a) * V(1, 1, 1) + a * V(0.5, 0.7, 1.0);
}

Group cover_scene() {
  Group g;
  g.items.push_back(std::make_shared<Sphere>(V(0, -1000, 0), 1000, std::make_shared<Diffuse>(V(0.5, 0.5, 0.5))));
  for (int a = -11; a < 11; a++)
    for (int b = -11; b < 11; b++) {
      double pick = uniform();
      V c(a + 0.9 * uniform(), 0.2, b + 0.9 * uniform());
      if ((c - V(4, 0.2, 0)).norm() <= 0.9) continue;
      std::shared_ptr<Material> m;
      if (pick < 0.8)
        m = std::make_shared<Diffuse>(random_v(0, 1) * random_v(0, 1));
      else if (pick < 0.95) {
        V alb = random_v(0.5, 1);
        m = std::make_shared<Metal>(alb, uniform(0, 0.5));
      } else
        m = std::make_shared<Glass>(1.5);
      g.items.push_back(std::make_shared<Sphere>(c, 0.2, m));
    }
  g.items.push_back(std::make_shared<Sphere>(V(0, 1, 0), 1.0, std::make_shared<Glass>(1.5)));
  g.items.push_back(std::make_shared<Sphere>(V(-4, 1, 0), 1.0, std::make_shared<Diffuse>(V(0.4, 0.2, 0.1))));
  g.items.push_back(std::make_shared<Sphere>(V(4, 1, 0), 1.0, std::make_shared<Metal>(V(0.7, 0.6, 0.5), 0.0)));
  return g;
}

}  // namespace

int main(int argc, char **argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: rtiow WIDTH HEIGHT SPP DEPTH > image.ppm\n");
    return 1;
  }
  const int w = std::atoi(argv[1]), h = std::atoi(argv[2]), spp = std::atoi(argv[3]), depth = std::atoi(argv[4]);
  if (w <= 0 || h <= 0 || spp <= 0 || depth <= 0) {
    std::fprintf(stderr, "rtiow: sizes must be positive\n");
    return 1;
  }
  Group world = cover_scene();

  // camera: from (13,2,3) towards the origin, 20 degrees vertically,
  // lens radius 0.05 focused at distance 10
  const V from(13, 2, 3), at(0, 0, 0), up(0, 1, 0);
  const double vfov = 20 * M_PI / 180, focus = 10, lens = 0.05;
  const double vh = 2 * std::tan(vfov / 2) * focus, vw = vh * w / h;
  const V back = unit(from - at), right = unit(cross(up, back)), upv = cross(back, right);
  const V du = (vw / w) * right, dv = (-vh / h) * upv;
  const V corner = from - focus * back - 0.5 * vw * right + 0.5 * vh * upv;

  std::vector<V> img(static_cast<size_t>(w) * h);
  auto t0 = std::chrono::steady_clock::now();
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) {
      V sum;
      for (int s = 0; s < spp; s++) {
        V target = corner + (i + uniform()) * du + (j + uniform()) * dv;
        V disk = in_unit_disk();
        V o = from + lens * disk.x * right + lens * disk.y * upv;
        sum += radiance({o, target - o}, depth, world);
      }
      img[static_cast<size_t>(j) * w + i] = sum / spp;
    }
  auto t1 = std::chrono::steady_clock::now();

  std::printf("P3\n%d %d\n255\n", w, h);
  for (const V &c : img) {
    auto byte = [](double x) {
      double g = x > 0 ? std::sqrt(x) : 0;
      return static_cast<int>(256 * (g < 0.999 ? g : 0.999));
    };
    std::printf("%d %d %d\n", byte(c.x), byte(c.y), byte(c.z));
  }
  std::fprintf(stderr, "spheres %zu\nseconds %.3f\n", world.items.size(),
               std::chrono::duration<double>(t1 - t0).count());
  return 0;
}
