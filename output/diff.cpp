#include "output/diff.h"
