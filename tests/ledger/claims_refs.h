/* Places of the paper the ledger cites from several files, in the notation (notation.h). */
#ifndef SUSLOV_CLAIMS_REFS_H
#define SUSLOV_CLAIMS_REFS_H

#define REF_CONCLUSIONS "Conclusions (\\PaperRefOr{nolabel:section-7})"
#define REF_SEC56 "\\PaperRefOr{nolabel:subsection-5.6} text"
#define REF_FIG2_CAPTION "\\PaperRefOr{Fig2} caption"
#define REF_FIG2_CONCLUSIONS REF_FIG2_CAPTION "; " REF_CONCLUSIONS
#define REF_FIG2_SEC56 REF_FIG2_CAPTION "; " REF_SEC56
#define REF_FIG2D "\\PaperRefOr{Fig2}, panel (d)"

/* "Much" (Figure 2's caption, the Conclusions) has no number in the paper, and no theory gives
 * one: our reading, an order of magnitude. The lines it governs also give their verdicts at factor
 * one, the weakest reading (claims_fig2more.c, claims_fig2_ranges.c, claims_fig2readings.c,
 * claims_sensitivity.c). */
#define CLAIMS_MUCH 10.0

#endif
