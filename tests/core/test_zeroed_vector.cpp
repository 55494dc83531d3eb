// ZeroedVector (core/zeroed_vector.h): growth into fresh storage gives zeros without writing them,
// also after release() of storage that held values; values asked for are written; a film
// reallocated over a rendered one starts at zero; large blocks (fresh pages), FillVector's too,
// behave the same.
#include <algorithm>
#include <catch2/catch.hpp>

#include "core/fill_vector.h"
#include "core/fresh_pages.h"
#include "core/render/film.h"
#include "core/zeroed_vector.h"

using namespace rt;

TEST_CASE("zeroed vector: new elements are zero in fresh storage, also after a release", "[zeroed]") {
  ZeroedVector<float> v(1000);
  for (const float x : v) REQUIRE(x == 0.0f);
  for (float& x : v) x = -1.0f;
  v.resize(5000);  // reallocated: the old values moved, the rest zero
  CHECK(v[999] == -1.0f);
  for (size_t i = 1000; i < v.size(); ++i) REQUIRE(v[i] == 0.0f);
  for (float& x : v) x = 7.5f;
  release(v);
  CHECK(v.empty());
  CHECK(v.capacity() == 0);
  v.resize(5000);
  for (const float x : v) REQUIRE(x == 0.0f);
  v.resize(6000, 2.0f);  // a value asked for is written
  CHECK(v[5999] == 2.0f);
  v.pop_back();
  v.push_back(3.0f);
  CHECK(v.back() == 3.0f);
}

TEST_CASE("zeroed vector: a film reallocated over a rendered one starts at zero", "[zeroed]") {
  Film film(64, 48);
  for (Vec3& p : film.color.pixels) p = Vec3(0.25f, 0.5f, 1.0f);
  for (uint16_t& n : film.samples) n = 9;
  for (uint8_t& d : film.depth) d = 3;
  REQUIRE(film.allocate(32, 24, nullptr));  // smaller
  for (Vec3& p : film.color.pixels) p = Vec3(0.5f);
  REQUIRE(film.allocate(80, 60, nullptr));  // larger again
  for (const Vec3& p : film.color.pixels) REQUIRE(p == Vec3(0.0f));
  for (const uint16_t n : film.samples) REQUIRE(n == 0);
  for (const uint8_t d : film.depth) REQUIRE(d == 0);
  for (Vec3& p : film.color.pixels) p = Vec3(1.0f);
  for (uint16_t& n : film.samples) n = 4;
  REQUIRE(film.allocate(80, 60, nullptr, rt::FilmChannels{.aovs = true}));  // the same size
  for (const Vec3& p : film.color.pixels) REQUIRE(p == Vec3(0.0f));
  for (const uint16_t n : film.samples) REQUIRE(n == 0);
  for (const Vec3& p : film.albedo.pixels) REQUIRE(p == Vec3(0.0f));
  for (Vec3& p : film.albedo.pixels) p = Vec3(1.0f);
  REQUIRE(film.allocate(80, 60, nullptr, rt::FilmChannels{.aovs = true}));  // the layers too
  for (const Vec3& p : film.albedo.pixels) REQUIRE(p == Vec3(0.0f));
  CHECK(Image(3, 2).pixels == ZeroedVector<Vec3>(6, Vec3(0.0f)));
}

TEST_CASE("zeroed vector: large blocks are fresh pages, zero, aligned, and grow and shrink as small ones do",
          "[zeroed]") {
  // 4 MiB and over: core/fresh_pages.h (2 MiB-aligned kernel pages on Linux; calloc's under ASan).
  const size_t large = kFreshPagesMin / sizeof(Vec3) + 1;
  ZeroedVector<Vec3> v(large);
  if (fresh_pages_from_kernel()) CHECK(reinterpret_cast<uintptr_t>(v.data()) % (size_t{2} << 20) == 0);
  CHECK(std::count(v.begin(), v.end(), Vec3(0.0f)) == static_cast<std::ptrdiff_t>(large));
  for (size_t i = 0; i < v.size(); ++i) v[i] = Vec3(static_cast<float>(i));
  v.resize(large + 123457);  // reallocated into a larger block: the values moved, the rest zero
  CHECK(v[large - 1] == Vec3(static_cast<float>(large - 1)));
  CHECK(v[12345] == Vec3(12345.0f));
  CHECK(std::count(v.begin() + static_cast<std::ptrdiff_t>(large), v.end(), Vec3(0.0f)) == 123457);
  v.back() = Vec3(5.0f);  // the block's last element is written and read back
  CHECK(v.back() == Vec3(5.0f));
  ZeroedVector<Vec3> small(1000, Vec3(1.0f));
  v.swap(small);  // a large block and a small one change hands and are each given back their own way
  CHECK(v.size() == 1000);
  CHECK(small.size() == large + 123457);
  release(small);
  release(v);
  ZeroedVector<uint8_t> bytes(kFreshPagesMin * 3 + 17);  // not a whole number of pages
  CHECK(std::count(bytes.begin(), bytes.end(), uint8_t{0}) == static_cast<std::ptrdiff_t>(bytes.size()));
  bytes.back() = 9;
  CHECK(bytes.back() == 9);
}

TEST_CASE("fill vector: large blocks are fresh pages too, and keep what was written as they grow", "[zeroed]") {
  // FillVector (core/fill_vector.h), the BVH's nodes, slots and quads: default-initialised
  // elements, written in full after; 4 MiB and over in fresh pages as ZeroedVector's.
  const size_t large = kFreshPagesMin / sizeof(uint32_t) + 5;
  FillVector<uint32_t> v;
  v.resize(large);
  if (fresh_pages_from_kernel()) CHECK(reinterpret_cast<uintptr_t>(v.data()) % (size_t{2} << 20) == 0);
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<uint32_t>(3 * i + 1);
  v.resize(2 * large);  // a larger block: the values moved
  size_t kept = 0;
  for (size_t i = 0; i < large; ++i) kept += v[i] == static_cast<uint32_t>(3 * i + 1);
  CHECK(kept == large);
  v.back() = 7u;
  CHECK(v.back() == 7u);
  FillVector<uint32_t> small(10, 2u);
  v.swap(small);
  CHECK(v.size() == 10);
  CHECK(small.size() == 2 * large);
  small.clear();
  small.shrink_to_fit();  // the large block given back
  CHECK(small.capacity() == 0);
}
