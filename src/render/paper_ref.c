#include "paper_ref.h"

#include <stdio.h>
#include <string.h>

const sus_paper_label *sus_paper_label_find(const char *label, size_t n)
{
    for (int i = 0; i < SUS_PAPER_NLABELS; i++)
        if (strlen(SUS_PAPER_LABELS[i].label) == n &&
            memcmp(SUS_PAPER_LABELS[i].label, label, n) == 0)
            return &SUS_PAPER_LABELS[i];
    return NULL;
}

/* "eq. (N)" for an equation; the kind capitalised before its number for anything else (a
 * subsection is a Section, as the paper refers to one). */
static void name_of(const sus_paper_label *p, char *buf, size_t len)
{
    const char *kind = p->kind;
    if (!strcmp(kind, "equation") || !strcmp(kind, "subequation")) {
        snprintf(buf, len, "eq. (%s)", p->number);
        return;
    }
    if (!strcmp(kind, "subsection"))
        kind = "section";
    snprintf(buf, len, "%c%s %s", kind[0] - 'a' + 'A', kind + 1, p->number);
}

const char *sus_paper_name(const char *label, char *buf, size_t len)
{
    const sus_paper_label *p = sus_paper_label_find(label, strlen(label));
    if (!p)
        return NULL;
    name_of(p, buf, len);
    return buf;
}

/* The characters of a label: letters, digits and the ":", "-" and "." of the unlabelled ones. */
static size_t label_span(const char *s)
{
    return strspn(s, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789:.-");
}

char *sus_paper_numbered(const char *text, char *out, size_t len)
{
    size_t o = 0;
    if (!len)
        return out;
    for (const char *p = text; *p && o + 1 < len;) {
        const size_t n = *p == '(' ? label_span(p + 1) : 0;
        const sus_paper_label *lab = n && p[n + 1] == ')' ? sus_paper_label_find(p + 1, n) : NULL;
        if (lab) {
            char name[64];
            name_of(lab, name, sizeof name);
            o += (size_t)snprintf(out + o, len - o, "%s", name);
            o = o < len ? o : len - 1;
            p += n + 2;
        } else {
            out[o++] = *p++;
        }
    }
    out[o] = '\0';
    return out;
}
