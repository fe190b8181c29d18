#include <cstdio>

int main(int argc, char** argv) {
    std::fprintf(stderr, "povwall: not implemented yet\n");
    return 2;
}
