/* (DistFinal), the display in the proof of Proposition 5.1 (TeoL): the expansion of R(t_k + eps)
 * it prints, R(t_k) + eps Ad_{R(t_k)} w^(t_k) + O(eps^2), against the one the text after it
 * implies (R' = (Ad_R w^) R = R w^), and whether the terms linear in eps cancel, as the proof says.
 */
#ifndef SUSLOV_CLAIMS_DISTFINAL_H
#define SUSLOV_CLAIMS_DISTFINAL_H

void distfinal_claims(void);

#endif
