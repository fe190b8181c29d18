# Writes quirks.ttf: a tiny TrueType font whose glyphs hit POV-Ray 3.7's reading quirks
# (scenes/golden/shape_text_quirks.pov): A two overlapping squares (even-odd: a hole),
# B a composite with byte offsets (-100 read unsigned as +156), C a square, D a contour
# starting off-curve, E a composite with a 2x2 shear (POV-Ray applies it transposed).
import struct
def simple(contours):
    # contours: list of lists of (x,y,on)
    pts=[p for c in contours for p in c]
    xs=[p[0] for p in pts]; ys=[p[1] for p in pts]
    hdr=struct.pack('>hhhhh',len(contours),min(xs),min(ys),max(xs),max(ys))
    ends=[];n=0
    for c in contours: n+=len(c); ends.append(n-1)
    b=hdr+struct.pack('>%dH'%len(ends),*ends)+struct.pack('>H',0)
    b+=bytes([1 if p[2] else 0 for p in pts])
    px=py=0
    for p in pts: b+=struct.pack('>h',p[0]-px); px=p[0]
    for p in pts: b+=struct.pack('>h',p[1]-py); py=p[1]
    if len(b)%2: b+=b'\0'
    return b
def sq(x0,y0,x1,y1): return [(x0,y0,1),(x0,y1,1),(x1,y1,1),(x1,y0,1)]  # clockwise
glyphs=[]
glyphs.append(simple([sq(0,0,100,100)]))                       # 0 notdef
glyphs.append(simple([sq(0,0,600,600),sq(300,300,900,900)]))   # 1 'A' overlapping squares
comp=struct.pack('>hhhhh',-1,-100,0,100,200)+struct.pack('>HHbb',0x0002,3,-100,0)  # 2 'B' composite, byte offsets (-100,0)
glyphs.append(comp+b'')
glyphs.append(simple([sq(0,0,200,200)]))                        # 3 'C' square
# 4 'D': circle-ish contour starting with an off-curve point
glyphs.append(simple([[(0,500,0),(500,500,1),(500,0,0),(0,0,1)]]))
# 5 'E': composite with 2x2 (shear) to test transpose: scale01=0.5
comp2=struct.pack('>hhhhh',-1,0,0,300,200)+struct.pack('>HHhh',0x0001|0x0002|0x0080,3,0,0)+struct.pack('>hhhh',0x4000,0x2000,0,0x4000)
glyphs.append(comp2)
ng=len(glyphs)
glyf=b''.join(glyphs); loca=[0]
for g in glyphs: loca.append(loca[-1]+len(g))
head=struct.pack('>IIIIHHQQhhhhHHhhh',0x10000,0x10000,0,0x5F0F3CF5,0,1000,0,0,-100,0,900,900,0,8,2,1,0)
hhea=struct.pack('>IhhhHhhhhhhhhhhhH',0x10000,800,-200,0,1000,0,0,900,1,0,0,0,0,0,0,0,ng)
hmtx=b''.join(struct.pack('>Hh',1000,[0,0,0,0,0,0][i]) for i in range(ng))
maxp=struct.pack('>IH',0x5000,ng)
locab=b''.join(struct.pack('>I',o) for o in loca)
arr=[0]*256
for ch,g in zip('ABCDE',range(1,6)): arr[ord(ch)]=g
sub=struct.pack('>HHH',0,262,0)+bytes(arr)
cmap=struct.pack('>HHHHI',0,1,1,0,12)+sub
tables={'cmap':cmap,'glyf':glyf,'head':head,'hhea':hhea,'hmtx':hmtx,'loca':locab,'maxp':maxp}
tags=sorted(tables); off=12+16*len(tags); out=b''; dirb=b''
for t in tags:
    d=tables[t]; dirb+=struct.pack('>4sIII',t.encode(),0,off+len(out),len(d)); out+=d+b'\0'*((4-len(d)%4)%4)
open('quirks.ttf','wb').write(struct.pack('>IHHHH',0x10000,len(tags),0,0,0)+dirb+out)
