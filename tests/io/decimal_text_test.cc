// io/decimal_text.h writes the characters std::to_chars writes (the CityJSON writer's output
// depends on it byte for byte). Checked here on every length's edges, on dense ranges and on a
// random sample; every 32-bit value was compared once by hand (about a minute).
#include "io/decimal_text.h"

#include <array>
#include <charconv>
#include <cstdint>
#include <limits>
#include <random>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

namespace insula::io {
namespace {

template <typename T>
void expect_as_to_chars(T value) {
  // Filled with a marker, so that a digit left unwritten shows.
  std::array<char, 32> ours;
  ours.fill('#');
  std::array<char, 32> theirs{};
  const char* end = decimal::write(ours.data(), value);
  const char* expected_end = std::to_chars(theirs.data(), theirs.data() + theirs.size(), value).ptr;
  ASSERT_EQ(std::string_view(ours.data(), static_cast<std::size_t>(end - ours.data())),
            std::string_view(theirs.data(), static_cast<std::size_t>(expected_end - theirs.data())))
      << value;
}

// 0, 1, 9, 10, 11, 99, 100, ... and the type's extremes.
template <typename T>
std::vector<T> edges() {
  std::vector<T> values{0, std::numeric_limits<T>::max(), std::numeric_limits<T>::min()};
  for (std::uint64_t power = 1; power <= std::numeric_limits<T>::max() / 10; power *= 10) {
    for (std::uint64_t near : {power - 1, power, power + 1, 10 * power - 1, 10 * power}) {
      values.push_back(static_cast<T>(near));
      if constexpr (std::numeric_limits<T>::is_signed) values.push_back(-static_cast<T>(near));
    }
  }
  return values;
}

TEST(DecimalText, Uint32Edges) {
  for (std::uint32_t value : edges<std::uint32_t>()) expect_as_to_chars(value);
}

TEST(DecimalText, Int64Edges) {
  for (std::int64_t value : edges<std::int64_t>()) expect_as_to_chars(value);
  // Around the two-word limit (10^16), where std::to_chars takes over.
  constexpr std::int64_t kSixteen = 10'000'000'000'000'000;
  for (std::int64_t d = -3; d <= 3; ++d) {
    expect_as_to_chars(kSixteen + d);
    expect_as_to_chars(-kSixteen + d);
  }
}

TEST(DecimalText, DenseRanges) {
  for (std::uint32_t value = 0; value < 2'000'000; ++value) expect_as_to_chars(value);
  for (std::uint32_t value = 99'000'000; value < 101'000'000; ++value) expect_as_to_chars(value);
  for (std::int64_t value = -1'000'000; value < 1'000'000; ++value) expect_as_to_chars(value);
}

TEST(DecimalText, RandomValues) {
  std::mt19937_64 random(17);
  for (int i = 0; i < 2'000'000; ++i) {
    const std::uint64_t bits = random();
    const unsigned shift = static_cast<unsigned>(random() % 64);
    expect_as_to_chars(static_cast<std::uint32_t>(bits >> (shift % 32)));
    expect_as_to_chars(static_cast<std::int64_t>(bits) >> shift);
  }
}

}  // namespace
}  // namespace insula::io
