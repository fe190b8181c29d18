#include "output/image_io.h"
