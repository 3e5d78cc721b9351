/* The paper's published numbering in the programs' texts (src/render/paper_ref.h): the compiled
 * table is paper/labels.tsv line for line (tools/paper_labels_c.sh writes it again when not),
 * names read as the paper prints them (the expected names are the paper's own numbers), and a
 * text's "(LABEL)" is replaced only where LABEL is one of the paper's. Run from the top of the
 * tree (make check does). */
#include "check.h"
#include "paper_ref.h"

#include <string.h>

/* Every line of paper/labels.tsv after its header against the table's entry in the same place. */
static void table_is_labels_tsv(void)
{
    FILE *fp = fopen("paper/labels.tsv", "r");
    CHECK(fp != NULL, "paper/labels.tsv opens (run from the top of the tree)");
    if (!fp)
        return;
    char line[256], want[256];
    int n = 0, same = 0;
    fgets(line, sizeof line, fp); /* the header */
    while (fgets(line, sizeof line, fp)) {
        line[strcspn(line, "\n")] = '\0';
        if (n < SUS_PAPER_NLABELS) {
            const sus_paper_label *p = &SUS_PAPER_LABELS[n];
            snprintf(want, sizeof want, "%s\t%s\t%s\t", p->label, p->kind, p->number);
            same += strncmp(line, want, strlen(want)) == 0;
        }
        n++;
    }
    fclose(fp);
    CHECK(n == SUS_PAPER_NLABELS && same == n,
          "the compiled table is paper/labels.tsv: %d of %d lines agree, the table has %d "
          "(else: sh tools/paper_labels_c.sh >src/render/paper_labels.c)",
          same, n, SUS_PAPER_NLABELS);
}

static void name_is(const char *label, const char *want)
{
    char buf[64];
    const char *got = sus_paper_name(label, buf, sizeof buf);
    CHECK(got && !strcmp(got, want), "%s is named '%s' (got '%s')", label, want,
          got ? got : "(none)");
}

static void numbered_is(const char *text, size_t len, const char *want)
{
    char out[256];
    sus_paper_numbered(text, out, len);
    CHECK(!strcmp(out, want), "'%s' in %zu bytes reads '%s' (got '%s')", text, len, want, out);
}

int main(void)
{
    table_is_labels_tsv();
    /* the paper's numbers, as it prints them */
    name_is("ContDyn", "eq. (27)");
    name_is("DEPEqa", "eq. (12a)");
    name_is("TeoL", "Proposition 5.1");
    name_is("PropoFinal", "Proposition 5.3");
    name_is("algo", "Algorithm 5.1");
    name_is("Fig2", "Figure 2");
    name_is("naturalCharts", "Section 4.1");
    name_is("Pertur", "Section 6");
    name_is("nolabel:proposition-5.2", "Proposition 5.2");
    char buf[64] = "kept";
    CHECK(sus_paper_name("Nope", buf, sizeof buf) == NULL && !strcmp(buf, "kept"),
          "a label the paper does not have has no name and leaves the buffer alone");
    numbered_is("from (LagMult) for every method", 256, "from eq. (28) for every method");
    numbered_is("((Discretization) with l), (TeoL)", 256, "(eq. (33) with l), Proposition 5.1");
    numbered_is("(a) w1, (Nope), (e.g.), (ContDyn", 256, "(a) w1, (Nope), (e.g.), (ContDyn");
    numbered_is("(nolabel:proposition-5.2) holds", 256, "Proposition 5.2 holds");
    numbered_is("see (ContDyn) here", 10, "see eq. (");
    numbered_is("(ContDyn)", 1, "");
    return check_summary("test_paper_ref");
}
