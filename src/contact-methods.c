/* The method table and the normal laws. A method is one file in src/methods/ and one row here;
   a normal law is one function in kernels/contact-law.h and one SPNormalLaw here. */
#include <spcontact-impl.h>

const SPNormalLaw SPLawShiftedPenalty = {"shifted_penalty", SPShiftedPenaltyTraction, SPShiftedPenaltyClosed};

/* the first row is the default method */
const SPMethod *const SPMethodTable[] = {&SPMethodShifted, &SPMethodPenalty, &SPMethodShiftedRegression, &SPMethodALM, NULL};
