// Embree 3 behind Intersectable: the scene's primitives in Embree's native and user geometries,
// the queries' state carried to the callbacks through the intersection context (EmbreeScene.h).
#include "embree/EmbreeScene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "bvh/BoundingBox.h"
#include "bvh/FloatBox.h"
#include "bvh/UnboundedShapes.h"
#include "intersections/HitRules.h"

namespace rt {

namespace {

enum class Kind : std::uint8_t { Sphere, Triangle, Quad, User };

const char* errorName(RTCError e) noexcept {
  switch (e) {
    case RTC_ERROR_NONE:
      return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN:
      return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION:
      return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED:
      return "RTC_ERROR_CANCELLED";
  }
  return "an unknown RTCError";
}

/// The float nearest x, and at least x (so that an interval ending at x keeps x): +inf beyond
/// the float range.
float floatAtLeast(double x) noexcept {
  if (!(x < static_cast<double>(std::numeric_limits<float>::max())))
    return std::numeric_limits<float>::infinity();
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

bool holdsBoundedBox(const std::optional<Aabb>& box) {
  if (!box) return false;
  const FloatBox b = conservativeBox(*box);
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return false;
  return true;
}

}  // namespace

struct EmbreeScene::Impl {
  Primitives primitives;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string lastMessage;
  std::vector<std::uint32_t> unbounded;
  /// Per Embree geometry (by its geomID): its kind, and the primitive of each of its primIDs.
  std::vector<Kind> kinds;
  std::vector<std::vector<std::uint32_t>> primitiveOf;
  unsigned userGeometry = RTC_INVALID_GEOMETRY_ID;  ///< the user geometry's geomID, if any

  explicit Impl(Primitives p) : primitives(p) {}
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  /// Throws when Embree reported an error since the last check.
  void check(const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e == RTC_ERROR_NONE) return;
    throw std::runtime_error(std::string("Embree: ") + errorName(e) + " while " + what +
                             (lastMessage.empty() ? "" : ": " + lastMessage));
  }

  unsigned attach(RTCGeometry g, Kind kind, std::vector<std::uint32_t> prims) {
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    check("attaching a geometry");
    if (id >= kinds.size()) {
      kinds.resize(id + 1);
      primitiveOf.resize(id + 1);
    }
    kinds[id] = kind;
    primitiveOf[id] = std::move(prims);
    return id;
  }

  /// The project's exact t for a native candidate of primitive p: the sphere's root on the side
  /// Embree reported (front: Ng against the ray), else the first root; nullopt when the exact
  /// test finds none there or it lies beyond tMax.
  std::optional<double> exactT(Kind kind, std::uint32_t p, const Ray& ray, const float ng[3],
                               double tMax) const noexcept {
    const Roots roots = primitives.roots(p, ray);
    if (roots.empty()) return std::nullopt;
    double t = roots[0];
    if (kind == Kind::Sphere) {
      const Double3& d = ray.direction().xyz();
      const bool front = d.x * ng[0] + d.y * ng[1] + d.z * ng[2] < 0;
      if (front && roots.size() < 2) return std::nullopt;
      t = front ? roots[0] : roots[roots.size() - 1];
    }
    if (!withinDistance(t, tMax)) return std::nullopt;
    return t;
  }
};

namespace {

/// A query's state on the caller's stack; Embree hands the context back to every callback.
struct Query {
  RTCIntersectContext context;  // first: the callbacks cast the context's address back
  const EmbreeScene::Impl* impl;
  const Ray* ray;
  double tMax;
  float tFar;  ///< floatAtLeast(tMax): the ray's far end for Embree, computed once per query
  const HitVisitor* visit;  // forEachHit; null for closestHit
  bool stopped = false;
  std::uint64_t tests = 0;
  /// closestHit: the best (t, primitive) pair the exact tests confirmed so far (the unbounded
  /// shapes' included): a candidate wins only when its exact pair is smaller, as NearestHit's.
  double bestT = INFINITE_DISTANCE;
  std::uint32_t bestPrimitive = 0;
  bool found = false;

  /// Takes (t, p) when it beats the best pair so far. @returns whether it did.
  bool offer(double t, std::uint32_t p) noexcept {
    if (found && !(t < bestT || (t == bestT && p < bestPrimitive))) return false;
    bestT = t;
    bestPrimitive = p;
    found = true;
    return true;
  }

  /// The ray's far end for Embree after a best pair: a little beyond bestT, so that a primitive
  /// hit at the same exact t (a face shared by two shapes), whose float t Embree computes a few
  /// ulps larger, is still offered and the smaller index wins. The margin, 2^-16 of the
  /// coordinates' size, is hundreds of float ulps: it costs a few exact tests, never an answer
  /// (the exact pair decides).
  float farEnd() const noexcept { return floatAtLeast(bestT + (bestT + scale) * 0x1p-16); }
  double scale = 0;  ///< the largest coordinate of the ray's origin, in absolute value
  std::array<std::uint32_t, EmbreeScene::QUAD_MEMORY> quads{};
  int quadCount = 0;

  /// True the first time quad p is seen (always true once the memory is full).
  bool firstVisitOfQuad(std::uint32_t p) noexcept {
    for (int i = 0; i < quadCount; ++i)
      if (quads[i] == p) return false;
    if (quadCount < EmbreeScene::QUAD_MEMORY) quads[quadCount++] = p;
    return true;
  }
};

Query& queryOf(RTCIntersectContext* c) noexcept { return *reinterpret_cast<Query*>(c); }

/// The context filter of both queries, for the native primitives (N = 1: rtcIntersect1,
/// rtcOccluded1).
void nativeFilter(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  Query& q = queryOf(args->context);
  const std::uint32_t geomID = RTCHitN_geomID(args->hit, args->N, 0);
  const Kind kind = q.impl->kinds[geomID];
  if (kind == Kind::User) return;  // the user callbacks decide themselves
  const std::uint32_t p = q.impl->primitiveOf[geomID][RTCHitN_primID(args->hit, args->N, 0)];
  if (q.visit != nullptr && q.stopped) return;  // accepted: rtcOccluded1 ends
  const float ng[3] = {RTCHitN_Ng_x(args->hit, args->N, 0), RTCHitN_Ng_y(args->hit, args->N, 0),
                       RTCHitN_Ng_z(args->hit, args->N, 0)};
  if (q.visit == nullptr) {  // closestHit: keep a candidate whose exact pair is the best
    ++q.tests;
    const std::optional<double> t = q.impl->exactT(kind, p, *q.ray, ng, q.tMax);
    if (!t || !q.offer(*t, p))
      args->valid[0] = 0;
    else  // accepted: Embree keeps the ray's far end the filter leaves
      RTCRayN_tfar(args->ray, args->N, 0) = std::min(q.farEnd(), q.tFar);
    return;
  }
  args->valid[0] = 0;  // forEachHit: visit, then let the walk go on
  if (kind == Kind::Quad && !q.firstVisitOfQuad(p)) return;
  ++q.tests;
  const std::optional<double> t = q.impl->exactT(kind, p, *q.ray, ng, q.tMax);
  if (t && !(*q.visit)(Hit{*t, p})) {
    q.stopped = true;
    args->valid[0] = -1;  // accepted: the walk ends
  }
}

void userBounds(const RTCBoundsFunctionArguments* args) {
  const auto* impl = static_cast<const EmbreeScene::Impl*>(args->geometryUserPtr);
  const std::uint32_t p = impl->primitiveOf[impl->userGeometry][args->primID];
  const FloatBox b = conservativeBox(*boundingBox(impl->primitives, p));
  *args->bounds_o = RTCBounds{b.lo[0], b.lo[1], b.lo[2], 0, b.hi[0], b.hi[1], b.hi[2], 0};
}

void userIntersect(const RTCIntersectFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  Query& q = queryOf(args->context);
  const std::uint32_t p = q.impl->primitiveOf[args->geomID][args->primID];
  ++q.tests;
  const Roots roots = q.impl->primitives.roots(p, *q.ray);
  if (roots.empty() || !withinDistance(roots[0], q.tMax) || !q.offer(roots[0], p)) return;
  RTCRayHit& rh = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  rh.ray.tfar = std::min(q.farEnd(), q.tFar);
  rh.hit.geomID = args->geomID;
  rh.hit.primID = args->primID;
  rh.hit.Ng_x = rh.hit.Ng_y = rh.hit.Ng_z = 0;
  rh.hit.u = rh.hit.v = 0;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

void userOccluded(const RTCOccludedFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  Query& q = queryOf(args->context);
  RTCRay& ray = *reinterpret_cast<RTCRay*>(args->ray);
  if (!q.stopped) {
    const std::uint32_t p = q.impl->primitiveOf[args->geomID][args->primID];
    ++q.tests;
    q.stopped = !visitHits(q.impl->primitives.roots(p, *q.ray), p, q.tMax, *q.visit);
  }
  if (q.stopped) ray.tfar = -std::numeric_limits<float>::infinity();  // occluded: the walk ends
}

/// The Embree ray of ray over (0, tMax].
RTCRay embreeRay(const Ray& ray, double tMax) noexcept {
  const Double3& o = ray.head().xyz();
  const Double3& d = ray.direction().xyz();
  RTCRay r{};
  r.org_x = static_cast<float>(o.x);
  r.org_y = static_cast<float>(o.y);
  r.org_z = static_cast<float>(o.z);
  r.dir_x = static_cast<float>(d.x);
  r.dir_y = static_cast<float>(d.y);
  r.dir_z = static_cast<float>(d.z);
  r.tnear = 0;
  r.tfar = floatAtLeast(tMax);
  r.mask = 0xFFFFFFFFu;
  r.time = 0;
  r.flags = 0;
  return r;
}

void initQuery(Query& q, const EmbreeScene::Impl* impl, const Ray& ray, double tMax,
               const HitVisitor* visit) noexcept {
  rtcInitIntersectContext(&q.context);
  q.context.filter = nativeFilter;
  q.impl = impl;
  q.ray = &ray;
  q.tMax = tMax;
  q.tFar = floatAtLeast(tMax);
  q.visit = visit;
  const Double3& o = ray.head().xyz();
  q.scale = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
}

}  // namespace

EmbreeScene::EmbreeScene(Primitives primitives) : impl_(std::make_unique<Impl>(primitives)) {
  Impl& m = *impl_;
  // One build thread: Embree starts no thread pool, and builds the same tree every time.
  m.device = rtcNewDevice("threads=1,set_affinity=0,verbose=0");
  if (m.device == nullptr)
    throw std::runtime_error(std::string("Embree: ") + errorName(rtcGetDeviceError(nullptr)) +
                             " while creating the device");
  rtcSetDeviceErrorFunction(
      m.device,
      [](void* user, RTCError, const char* text) {
        static_cast<Impl*>(user)->lastMessage = text != nullptr ? text : "";
      },
      &m);
  m.scene = rtcNewScene(m.device);
  m.check("creating the scene");
  rtcSetSceneFlags(m.scene, static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST |
                                                       RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
  rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_MEDIUM);

  // Sort the primitives by kind.
  std::vector<std::uint32_t> spheres, triangles, quads, user;
  const std::span<const Geometry> shapes = primitives.shapes();
  for (std::uint32_t i = 0; i < primitives.size(); ++i) {
    if (!holdsBoundedBox(boundingBox(primitives, i))) {
      m.unbounded.push_back(i);
      continue;
    }
    if (!primitives.isShape(i)) {
      triangles.push_back(i);
      continue;
    }
    const Geometry& g = shapes[i];
    if (std::holds_alternative<Sphere>(g))
      spheres.push_back(i);
    else if (std::holds_alternative<Triangle>(g))
      triangles.push_back(i);
    else if (const auto* poly = std::get_if<Polygon>(&g); poly && poly->vertices().size() == 4)
      quads.push_back(i);
    else
      user.push_back(i);
  }
  const auto put = [](float* out, const Point& p) {
    out[0] = static_cast<float>(p.xyz().x);
    out[1] = static_cast<float>(p.xyz().y);
    out[2] = static_cast<float>(p.xyz().z);
  };

  if (!spheres.empty()) {
    RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), spheres.size()));
    m.check("allocating the spheres");
    for (std::size_t k = 0; k < spheres.size(); ++k) {
      const Sphere& s = std::get<Sphere>(shapes[spheres[k]]);
      put(v + 4 * k, s.center());
      v[4 * k + 3] = static_cast<float>(s.radius());
    }
    m.attach(g, Kind::Sphere, std::move(spheres));
  }
  if (!triangles.empty()) {
    RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * triangles.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
    m.check("allocating the triangles");
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      const std::uint32_t i = triangles[k];
      std::array<Point, 3> corners{Point(0, 0, 0), Point(0, 0, 0), Point(0, 0, 0)};
      if (primitives.isShape(i)) {
        corners = std::get<Triangle>(shapes[i]).vertices();
      } else {
        const MeshTriangle mt = primitives.meshTriangle(i);
        const TriangleMesh& mesh = *primitives.meshes()[mt.mesh].mesh;
        const auto& tri = mesh.triangles()[mt.triangle];
        for (int c = 0; c < 3; ++c) corners[c] = mesh.vertices()[tri[c]];
      }
      for (int c = 0; c < 3; ++c) {
        put(v + 9 * k + 3 * c, corners[c]);
        idx[3 * k + c] = static_cast<unsigned>(3 * k + c);
      }
    }
    m.attach(g, Kind::Triangle, std::move(triangles));
  }
  if (!quads.empty()) {
    RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_QUAD);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * quads.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), quads.size()));
    m.check("allocating the quads");
    for (std::size_t k = 0; k < quads.size(); ++k) {
      const auto& corners = std::get<Polygon>(shapes[quads[k]]).vertices();
      for (int c = 0; c < 4; ++c) {
        put(v + 12 * k + 3 * c, corners[c]);
        idx[4 * k + c] = static_cast<unsigned>(4 * k + c);
      }
    }
    m.attach(g, Kind::Quad, std::move(quads));
  }
  if (!user.empty()) {
    RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(user.size()));
    rtcSetGeometryUserData(g, &m);
    rtcSetGeometryBoundsFunction(g, userBounds, &m);
    rtcSetGeometryIntersectFunction(g, userIntersect);
    rtcSetGeometryOccludedFunction(g, userOccluded);
    m.check("making the user geometry");
    m.userGeometry = m.attach(g, Kind::User, std::move(user));
  }
  rtcCommitScene(m.scene);
  m.check("building the scene");
}

EmbreeScene::~EmbreeScene() = default;

std::optional<Hit> EmbreeScene::closestHit(const Ray& ray, double tMax,
                                           QueryCounts* counts) const noexcept {
  const Impl& m = *impl_;
  NearestHit nearest(tMax);
  std::uint64_t tests = offerUnbounded(m.unbounded, m.primitives, ray, nearest);
  if (!m.kinds.empty()) {
    Query q;
    initQuery(q, &m, ray, tMax, nullptr);
    RTCRayHit rh{};
    rh.ray = embreeRay(ray, tMax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (const std::optional<Hit> h = nearest.hit()) {  // an unbounded shape's hit
      q.offer(h->t, h->geometry);
      rh.ray.tfar = std::min(q.farEnd(), rh.ray.tfar);
    }
    rtcIntersect1(m.scene, &q.context, &rh);
    tests += q.tests;
    addQueryCounts(counts, tests, 0);
    return q.found ? std::optional<Hit>(Hit{q.bestT, q.bestPrimitive}) : std::nullopt;
  }
  addQueryCounts(counts, tests, 0);
  return nearest.hit();
}

bool EmbreeScene::forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                             QueryCounts* counts) const {
  const Impl& m = *impl_;
  std::uint64_t tests = 0;
  bool complete = visitUnbounded(m.unbounded, m.primitives, ray, tMax, visit, tests);
  if (complete && !m.kinds.empty()) {
    Query q;
    initQuery(q, &m, ray, tMax, &visit);
    RTCRay r = embreeRay(ray, tMax);
    rtcOccluded1(m.scene, &q.context, &r);
    tests += q.tests;
    complete = !q.stopped;
  }
  addQueryCounts(counts, tests, 0);
  return complete;
}

EmbreeScene::Census EmbreeScene::census() const noexcept {
  Census c;
  c.unbounded = static_cast<std::uint32_t>(impl_->unbounded.size());
  for (std::size_t g = 0; g < impl_->kinds.size(); ++g) {
    const auto n = static_cast<std::uint32_t>(impl_->primitiveOf[g].size());
    switch (impl_->kinds[g]) {
      case Kind::Sphere:
        c.spheres += n;
        break;
      case Kind::Triangle:
        c.triangles += n;
        break;
      case Kind::Quad:
        c.quads += n;
        break;
      case Kind::User:
        c.user += n;
        break;
    }
  }
  return c;
}

const char* EmbreeScene::version() noexcept { return RTC_VERSION_STRING; }

}  // namespace rt
