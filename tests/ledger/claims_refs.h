/* Places of the paper the ledger cites from several files, in the notation (notation.h). */
#ifndef SUSLOV_CLAIMS_REFS_H
#define SUSLOV_CLAIMS_REFS_H

#define REF_CONCLUSIONS "Conclusions (\\PaperRefOr{nolabel:section-7})"
#define REF_SEC56 "\\PaperRefOr{nolabel:subsection-5.6} text"
#define REF_FIG2_CAPTION "\\PaperRefOr{Fig2} caption"
#define REF_FIG2_CONCLUSIONS REF_FIG2_CAPTION "; " REF_CONCLUSIONS
#define REF_FIG2_SEC56 REF_FIG2_CAPTION "; " REF_SEC56
#define REF_FIG2D "\\PaperRefOr{Fig2}, panel (d)"

#endif
