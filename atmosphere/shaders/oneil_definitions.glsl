// O'Neil 2005's scale function as the shaders and its C++ side
// (atmosphere/math/oneil_math.h) share it; the functions and the derivation
// are in oneil_functions.glsl. Degrees: Earth, Mars and the asteroid fit
// within the figures in oneil_math.h's fit (see `planet probe oneil-fit`).
const int kOneilXTerms = 6;
const int kOneilYTerms = 4;
const int kOneilTerms = kOneilXTerms * kOneilYTerms;
const int kOneilChapter = 1;
const int kOneilFitted = 0;

// The scale function of one exponential component.
struct OneilScale {
  Real scale_height;  // H, metres
  int kind;           // kOneilFitted or kOneilChapter
  // c[i * kOneilYTerms + j] multiplies x^(i + 1) y^j (fitted kind only).
  Real c[kOneilTerms];
};

