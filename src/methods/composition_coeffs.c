/* Weights of symmetric composition methods, half-sequences g_1..g_m with the middle weight last
 * (the full sequence is palindromic, s = 2m - 1 stages). Every table's order is measured by the
 * claims ledger before it is trusted (tests/ledger/claims_highorder.c): a wrong digit or sign shows
 * as an order of 2. Triple jump (s = 3) and McLachlan's s = 15 were measured too and left out: at
 * equal cost, Suzuki's s = 5 was 60x and Kahan-Li's s = 17 20x more accurate on this problem. */
#include "composition.h"

/* Order 4, s = 5 (Suzuki 1990; HLW Sect. V.3): p = 1/(4 - 4^(1/3)), weights p, p, 1 - 4p, p, p. */
static const double SZ4[] = {0.41449077179437573714235406, 0.41449077179437573714235406,
                             -0.65796308717750294856941625};

/* Order 6, s = 9 (Kahan & Li 1997, Math. Comp. 66, 1089; HLW Sect. V.3); copied from SciML
 * OrdinaryDiffEq.jl lib/OrdinaryDiffEqSymplecticRK/src/symplectic_tableaus.jl (KahanLi6),
 * cross-checked against hannorein/rebound src/integrator_janus.c. */
static const double KL6[] = {0.39216144400731413927925056, 0.33259913678935943859974864,
                             -0.70624617255763935980996482, 0.08221359629355080023149045,
                             0.79854399093482996339895035};

/* Order 8, s = 17 (Kahan & Li 1997; HLW Sect. V.3); same sources as KL6 (KahanLi8). */
static const double KL8[] = {
    0.13020248308889008087881763, 0.56116298177510838456196441,  -0.38947496264484728640807860,
    0.15884190655515560089621075, -0.39590389413323757733623154, 0.18453964097831570709183254,
    0.25837438768632204729397911, 0.29501172360931029887096624,  -0.60550853383003451169892108};

/* Order 10, s = 35 (Sofroniou & Spaletta 2005, Optim. Methods Softw. 20, 597; HLW 2nd ed.
 * Sect. V.3). The brief called it "Kahan-Li 35"; Kahan & Li's own order-10 schemes have s = 31
 * and 33, and the s = 35 scheme everyone ships is this one. Copied from SciML OrdinaryDiffEq.jl
 * symplectic_tableaus.jl (SofSpa10ConstantCache, a1..a18, the composition weights). */
static const double SS10[] = {
    0.07879572252168641926390768,  0.31309610341510852776481247,  0.02791838323507806610952027,
    -0.22959284159390709415121340, 0.13096206107716486317465686,  -0.26973340565451071434460973,
    0.07497334315589143566613711,  0.11199342399981020488957508,  0.36613344954622675119314812,
    -0.39910563013603589787862981, 0.10308739852747107731580277,  0.41143087395589023782070412,
    -0.00486636058313526176219566, -0.39203335370863990644808194, 0.05194250296244964703718290,
    0.05066509075992449633587434,  0.04967437063972987905456880,  0.04931773575959453791768001};

#define HALF(a) ((int)(sizeof a / sizeof a[0]))

const sus_step_composition sus_step_comp_suzuki4 = {"Suzuki s=5", "Suzuki 1990; HLW Sect. V.3", 4,
                                                    HALF(SZ4), SZ4};
const sus_step_composition sus_step_comp_kahan_li6 = {
    "Kahan-Li s=9", "Kahan & Li 1997; HLW Sect. V.3", 6, HALF(KL6), KL6};
const sus_step_composition sus_step_comp_kahan_li8 = {
    "Kahan-Li s=17", "Kahan & Li 1997; HLW Sect. V.3", 8, HALF(KL8), KL8};
const sus_step_composition sus_step_comp_sofroniou10 = {
    "Sofroniou-Spaletta s=35", "Sofroniou & Spaletta 2005; HLW Sect. V.3", 10, HALF(SS10), SS10};
