#include "paper_labels.h"

#include "ledger.h"

#include <stdio.h>
#include <string.h>

#define LABELS_PATH "paper/labels.tsv"
#define LABELS_MAX 256

typedef struct {
    char label[48], kind[16], number[12];
} paper_label;

static paper_label table[LABELS_MAX];
static int nlabels = -1; /* -1: not read yet */

/* Reads the table once: label, kind and number of each row after the header. */
static void read_table(void)
{
    FILE *fp = fopen(LABELS_PATH, "r");
    char line[256];
    if (!fp)
        ledger_die("reading " LABELS_PATH " (run from the repository's root)");
    nlabels = 0;
    while (fgets(line, sizeof line, fp)) {
        paper_label *p = &table[nlabels];
        if (strncmp(line, "label\t", 6) == 0)
            continue;
        if (nlabels == LABELS_MAX ||
            sscanf(line, "%47[^\t]\t%15[^\t]\t%11[^\t\n]", p->label, p->kind, p->number) != 3) {
            fclose(fp);
            ledger_die("parsing " LABELS_PATH);
        }
        nlabels++;
    }
    fclose(fp);
}

static const paper_label *find(const char *label, size_t n)
{
    if (nlabels < 0)
        read_table();
    for (int i = 0; i < nlabels; i++)
        if (strlen(table[i].label) == n && strncmp(table[i].label, label, n) == 0)
            return &table[i];
    return NULL;
}

const char *paper_label_name(const char *label, size_t n, int bare, char *buf, size_t len)
{
    const paper_label *p = find(label, n);
    if (!p)
        return NULL;
    if (strcmp(p->kind, "equation") == 0 || strcmp(p->kind, "subequation") == 0)
        snprintf(buf, len, "%s(%s)", bare ? "" : "eq. ", p->number);
    else /* a subsection is a Section to the reader, as the paper prints it */
        snprintf(buf, len, "%c%s %s", p->kind[0] - 'a' + 'A',
                 strcmp(p->kind, "subsection") == 0 ? "ection" : p->kind + 1, p->number);
    return buf;
}

int paper_label_is_stand_in(const char *label, size_t n)
{
    return n > 8 && strncmp(label, "nolabel:", 8) == 0;
}
