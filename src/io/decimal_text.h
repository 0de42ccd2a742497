// Decimal text of integers, the same characters std::to_chars writes, formed eight digits at a time
// in one 64-bit register (SWAR: four 16-bit, then eight 8-bit lanes split by multiplications)
// rather than two by two from the end through a table. A CityJSON file is mostly integers
// (vertex numbers and millimetre coordinates); std::to_chars spent a third of its time finding a
// number's length and a table load per pair of digits.
//
// The writers store whole 8-byte words: `at` needs room for as many bytes as std::to_chars could
// write (10 for 32 bits, 20 for 64) even when fewer come, and bytes past the returned end may be
// overwritten.
#pragma once

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace insula::io::decimal {

static_assert(std::endian::native == std::endian::little,
              "digits are stored as little-endian words");

// The eight digits of `value` (< 10^8, leading zeros kept) as a word whose bytes, in memory order,
// are the digits' values 0..9, most significant first. From Daniel Lemire's "Converting integers to
// fix-digit representations quickly" (2021): the two halves of 4 digits go into two 32-bit lanes,
// each divided by 100 (x 10486 >> 20), the results into four 16-bit lanes divided by 10 (x 103 >>
// 10); quotient and remainder land in adjacent lanes, the quotient first.
inline std::uint64_t digit_values(std::uint32_t value) {
  const std::uint64_t merged = (value / 10000) | (std::uint64_t{value % 10000} << 32U);
  const std::uint64_t hundreds = ((merged * 10486U) >> 20U) & 0x0000007F'0000007FULL;
  const std::uint64_t pairs = ((merged - 100 * hundreds) << 16U) + hundreds;
  std::uint64_t tens = ((pairs * 103U) >> 10U) & 0x000F000F'000F000FULL;
  tens += (pairs - 10 * tens) << 8U;
  return tens;
}

// The eight digits of `value` < 10^8, leading zeros kept.
inline char* eight_digits(char* at, std::uint32_t value) {
  const std::uint64_t text = digit_values(value) + 0x30303030'30303030ULL;
  std::memcpy(at, &text, sizeof text);
  return at + 8;
}

// `value` < 10^8 without leading zeros ("0" for 0). The leading zero digits are the low zero bytes
// of the word; bit 56 set beforehand counts at most 7 of them, keeping the last digit.
inline char* up_to_eight_digits(char* at, std::uint32_t value) {
  const std::uint64_t digits = digit_values(value);
  const int zeros = std::countr_zero(digits | (std::uint64_t{1} << 56U)) / 8;
  const std::uint64_t text = (digits + 0x30303030'30303030ULL) >> (8 * zeros);
  std::memcpy(at, &text, sizeof text);
  return at + 8 - zeros;
}

// Up to 10 digits.
inline char* write(char* at, std::uint32_t value) {
  constexpr std::uint32_t kEight = 100'000'000;
  if (value < kEight) return up_to_eight_digits(at, value);
  const std::uint32_t high = value / kEight;  // 1 .. 42
  if (high >= 10) *at++ = static_cast<char>('0' + high / 10);
  *at++ = static_cast<char>('0' + high % 10);
  return eight_digits(at, value % kEight);
}

// Up to 20 characters, a '-' first when negative. Below 10^16 in magnitude (any coordinate that
// can be written) in two words; std::to_chars beyond.
inline char* write(char* at, std::int64_t value) {
  constexpr std::uint64_t kEight = 100'000'000;
  constexpr std::uint64_t kSixteen = kEight * kEight;
  std::uint64_t magnitude = static_cast<std::uint64_t>(value);
  if (value < 0) {
    *at++ = '-';
    magnitude = 0 - magnitude;
  }
  if (magnitude < kEight) return up_to_eight_digits(at, static_cast<std::uint32_t>(magnitude));
  if (magnitude >= kSixteen) return std::to_chars(at, at + 20, magnitude).ptr;
  at = up_to_eight_digits(at, static_cast<std::uint32_t>(magnitude / kEight));
  return eight_digits(at, static_cast<std::uint32_t>(magnitude % kEight));
}

}  // namespace insula::io::decimal
