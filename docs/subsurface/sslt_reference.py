#!/usr/bin/env python3
"""Reference numbers for the SSLT spec (independent re-derivation from the math, not POV-Ray code).
Prints: Fdr(eta), reduced-albedo table samples, mt19937-based epsilon stream, Halton sphere directions,
and a worked diffuse-dipole example."""
import math, struct

def fdr(eta):
    if eta < 1.0: return eta*eta - eta**2.25
    t = 1.0 - 1.0/eta
    return (t + 3.0*t**4.5) / 4.0

def rd_uniform(A, a):            # multiple-scattering albedo of a semi-infinite slab (Jensen 2001 eq. 5 form)
    r = math.sqrt(3.0*(1.0-a))
    return 0.5*a*(1.0 + math.exp(-4.0/3.0*A*r))*math.exp(-r)

def f32(x): return struct.unpack('f', struct.pack('f', x))[0]

def albedo_table(ior, n=100, tol=1e-10):
    A = (1+fdr(ior))/(1-fdr(ior))
    tab = [0.0]*(n+1); tab[n] = 1.0
    a, R = 1.0, 1.0
    for i in range(n-1, 0, -1):
        target = i/n
        a0, R0, a1, R1 = 0.0, 0.0, a, R
        while abs(R-target) >= tol:          # regula falsi, bracket [a0,a1]
            a = a0 + (target-R0)/(R1-R0)*(a1-a0)
            R = rd_uniform(A, a)
            if R < target: a0, R0 = a, R
            else: a1, R1 = a, R
        tab[i] = f32(a)
    return tab

def lookup(tab, R, n=100):
    x = R*n; i0 = math.floor(x); i1 = math.ceil(x); p = x-i0
    return (1-p)*tab[i0] + p*tab[i1]

class MT19937:
    def __init__(self, seed=5489):
        self.mt=[0]*624; self.mt[0]=seed
        for i in range(1,624):
            self.mt[i]=(1812433253*(self.mt[i-1]^(self.mt[i-1]>>30))+i)&0xffffffff
        self.i=624
    def __call__(self):
        if self.i>=624:
            for k in range(624):
                y=(self.mt[k]&0x80000000)|(self.mt[(k+1)%624]&0x7fffffff)
                self.mt[k]=self.mt[(k+397)%624]^(y>>1)^(0x9908b0df if y&1 else 0)
            self.i=0
        y=self.mt[self.i]; self.i+=1
        y^=y>>11; y^=(y<<7)&0x9d2c5680; y^=(y<<15)&0xefc60000; y^=y>>18
        return y

def halton(i, base):                 # i >= 1
    h, q = 0.0, 1.0/base
    while i > 0:
        h += (i % base)*q; i //= base; q /= base
    return h

def sphere_dir(k):                   # k = 0-based table index
    x = -1.0 + halton(k+1, 2)*2.0
    r = math.sqrt(1-x*x); th = halton(k+1, 3)*2*math.pi
    return (x, r*math.cos(th), r*math.sin(th))

def ft(cos_t, eta):                  # 1 - unpolarised Fresnel reflectance
    g2 = eta*eta + cos_t*cos_t - 1
    if g2 < 0: return 1.0            # NaN in C -> clamp(NaN) yields 0 reflectance
    g = math.sqrt(g2); c = cos_t
    F = 0.5*((g-c)**2/(g+c)**2)*(1 + (c*(g+c)-1)**2/(c*(g-c)+1)**2)
    return 1.0 - min(1.0, max(0.0, F))

if __name__ == '__main__':
    for ior in (1.0, 1.3, 1.45, 1.5):
        t = albedo_table(ior)
        print("ior %.2f Fdr=%.9f A=%.9f  alpha'(Rd): " % (ior, fdr(ior), (1+fdr(ior))/(1-fdr(ior))) +
              " ".join("%.3f->%.7f" % (R, lookup(t, R)) for R in (0.008, 0.05, 0.25, 0.5, 0.664, 0.72, 0.9, 0.99)))
    g = MT19937(); tab = [g()/4294967296.0 for _ in range(12)]
    print("mt19937 u[k]=out_k/2^32, k=0..11:", ["%.10f" % v for v in tab])
    print("SSLT epsilon stream starts at k=1:", ["%.10f" % v for v in tab[1:6]])
    print("Halton sphere directions k=0..5:")
    for k in range(6): print("  ", k, tuple("%.9f" % c for c in sphere_dir(k)))
    # worked example: diffuse term, one channel
    eta, sps, Rd_in = 1.3, 1.0/1.2, 0.9*0.8     # translucency 1.2 mm, pigment 0.9 * diffuse 0.8
    a = lookup(albedo_table(1.3), Rd_in)
    spt = sps/a; sa = spt - sps; str_ = math.sqrt(3*sa*spt)
    A = (1+fdr(eta))/(1-fdr(eta)); zr = 1/spt; zv = zr*(1+4*A/3)
    for r in (0.0, 0.5, 2.0):
        dr = math.sqrt(zr*zr+r*r); dv = math.sqrt(zv*zv+r*r)
        Rd = a/(4*math.pi)*(zr*(str_+1/dr)*math.exp(-str_*dr)/dr**2 + zv*(str_+1/dv)*math.exp(-str_*dv)/dv**2)
        print("example eta=1.3 transl=1.2mm Rd_in=0.72: alpha'=%.7f sigma't=%.6f sigma_a=%.6f sigma_tr=%.6f r=%.1fmm Rd(r)=%.8e Ft(cos=1)=%.7f Ft(cos=0.5)=%.7f"
              % (a, spt, sa, str_, r, Rd, ft(1.0, eta), ft(0.5, eta)))
