// Unit tests of the strict value parsers of `rt` (cli/Values.h).
#include <gtest/gtest.h>

#include <string>

#include "cli/CommandLine.h"
#include "cli/Values.h"

namespace rt::cli {
namespace {

template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ValuesTests, parseInt) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an integer inside the range
  EXPECT_EQ(parseInt("640", "--width", 1, 32768), 640);
  // TC02: not a number
  EXPECT_EQ(errorOf([] { parseInt("wide", "--width", 1, 32768); }),
            "--width: expected an integer from 1 to 32768, got 'wide'");
  // TC03: a number followed by garbage
  EXPECT_EQ(errorOf([] { parseInt("64x", "--width", 1, 32768); }),
            "--width: expected an integer from 1 to 32768, got '64x'");
  // TC04: a fraction
  EXPECT_EQ(errorOf([] { parseInt("6.5", "--width", 1, 32768); }),
            "--width: expected an integer from 1 to 32768, got '6.5'");
  // TC05: any JSON number form of an integer (the app's one rule, as in scene files)
  EXPECT_EQ(parseInt("1e2", "--pixel X", 0, 999), 100);
  EXPECT_EQ(parseInt("100.0", "--pixel X", 0, 999), 100);
  // TC06: forms JSON does not have
  EXPECT_EQ(errorOf([] { parseInt("+5", "--pixel X", 0, 999); }),
            "--pixel X: expected an integer from 0 to 999, got '+5'");
  EXPECT_EQ(errorOf([] { parseInt("05", "--pixel X", 0, 999); }),
            "--pixel X: expected an integer from 0 to 999, got '05'");
  // =============== Boundary Values Tests ==================
  // TC11, TC12: the range's ends are accepted
  EXPECT_EQ(parseInt("1", "--width", 1, 32768), 1);
  EXPECT_EQ(parseInt("32768", "--width", 1, 32768), 32768);
  // TC13, TC14: one beyond each end is refused
  EXPECT_EQ(errorOf([] { parseInt("0", "--width", 1, 32768); }),
            "--width: expected an integer from 1 to 32768, got '0'");
  EXPECT_EQ(errorOf([] { parseInt("32769", "--height", 1, 32768); }),
            "--height: expected an integer from 1 to 32768, got '32769'");
  // TC15: far beyond the range of int (no overflow into the range)
  EXPECT_EQ(errorOf([] { parseInt("4294967297", "--width", 1, 32768); }),
            "--width: expected an integer from 1 to 32768, got '4294967297'");
  // TC16: the empty string
  EXPECT_EQ(errorOf([] { parseInt("", "--width", 1, 32768); }),
            "--width: expected an integer from 1 to 32768, got ''");
}

TEST(ValuesTests, parseDouble) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a negative decimal
  EXPECT_EQ(parseDouble("-0.5", "x"), -0.5);
  // TC02: scientific notation
  EXPECT_EQ(parseDouble("1e-3", "x"), 1e-3);
  // TC03: not a number
  EXPECT_EQ(errorOf([] { parseDouble("abc", "x"); }), "x: expected a finite number, got 'abc'");
  // =============== Boundary Values Tests ==================
  // TC11, TC12: infinity and NaN are refused
  EXPECT_EQ(errorOf([] { parseDouble("inf", "x"); }), "x: expected a finite number, got 'inf'");
  EXPECT_EQ(errorOf([] { parseDouble("nan", "x"); }), "x: expected a finite number, got 'nan'");
  // TC13: a number too large for a double
  EXPECT_EQ(errorOf([] { parseDouble("1e400", "x"); }), "x: expected a finite number, got '1e400'");
}

TEST(ValuesTests, parseTriple) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: three numbers, negative ones included
  const Double3 v = parseTriple("-1,0.5,-2", "--ray origin");
  EXPECT_EQ(v.x, -1);
  EXPECT_EQ(v.y, 0.5);
  EXPECT_EQ(v.z, -2);
  // TC02: one of them is not a number
  EXPECT_EQ(errorOf([] { parseTriple("1,y,3", "--ray origin"); }),
            "--ray origin: expected 3 comma-separated finite numbers, got '1,y,3' ('y' is not "
            "one)");
  // =============== Boundary Values Tests ==================
  // TC11: two numbers
  EXPECT_EQ(errorOf([] { parseTriple("1,2", "--ray origin"); }),
            "--ray origin: expected 3 comma-separated numbers, got '1,2'");
  // TC12: four numbers
  EXPECT_EQ(errorOf([] { parseTriple("1,2,3,4", "--ray origin"); }),
            "--ray origin: expected 3 comma-separated numbers, got '1,2,3,4'");
  // TC13: an empty item
  EXPECT_EQ(errorOf([] { parseTriple("1,,3", "--ray origin"); }),
            "--ray origin: expected 3 comma-separated finite numbers, got '1,,3' ('' is not one)");
}

TEST(ValuesTests, parseIntPair) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a pixel inside the image
  EXPECT_EQ(parseIntPair("3,4", "--pixel", 9, 9), (std::array<int, 2>{3, 4}));
  // TC02: no comma
  EXPECT_EQ(errorOf([] { parseIntPair("34", "--pixel", 9, 9); }),
            "--pixel: expected X,Y, got '34'");
  // =============== Boundary Values Tests ==================
  // TC11: the last column and row
  EXPECT_EQ(parseIntPair("9,7", "--pixel", 9, 7), (std::array<int, 2>{9, 7}));
  // TC12: one column beyond the image
  EXPECT_EQ(errorOf([] { parseIntPair("10,0", "--pixel", 9, 7); }),
            "--pixel X: expected an integer from 0 to 9, got '10'");
  // TC13: a negative row
  EXPECT_EQ(errorOf([] { parseIntPair("0,-1", "--pixel", 9, 7); }),
            "--pixel Y: expected an integer from 0 to 7, got '-1'");
}

}  // namespace
}  // namespace rt::cli
