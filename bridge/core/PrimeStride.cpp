#include "bridge/core/PrimeStride.h"

namespace eikon {

long long largestPrimeAtMost(long long n) {
    for (long long k = n; k >= 2; --k) {
        bool prime = true;
        for (long long d = 2; d * d <= k && prime; ++d) prime = k % d != 0;
        if (prime) return k;
    }
    return 1;
}

}  // namespace eikon
