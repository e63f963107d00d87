import json, math
def circle(cx, cy, R, ccw=True):
    segs = []
    w = math.cos(math.pi/4)
    sgn = 1 if ccw else -1
    for k in range(4):
        s = sgn*k*math.pi/2; e = sgn*(k+1)*math.pi/2; m = (s+e)/2
        P = lambda a, r=R: [round(cx + r*math.cos(a), 12), round(cy + r*math.sin(a), 12)]
        segs.append({"type": "bezier", "points": [P(s), P(m, R/w), P(e)], "weights": [1, w, 1]})
    segs[-1]["points"][-1] = segs[0]["points"][0]
    return {"type": "path", "closed": True, "segments": segs}
def arc(cx, cy, R, a0, a1):
    # a0 -> a1 (radians), split into <= 90 degree rational quadratics
    n = max(1, math.ceil(abs(a1-a0)/(math.pi/2) - 1e-9)); th = (a1-a0)/n; out=[]
    for k in range(n):
        s=a0+k*th; e=s+th; m=(s+e)/2; w=math.cos(th/2)
        P=lambda a, r=R: [round(cx+r*math.cos(a),12), round(cy+r*math.sin(a),12)]
        out.append({"type":"bezier","points":[P(s),P(m,R/w),P(e)],"weights":[1,w,1]})
    return out
def line(a,b): return {"type":"bezier","points":[a,b]}
def join(segs):
    # make ends exactly equal
    for i in range(1,len(segs)): segs[i]["points"][0] = segs[i-1]["points"][-1]
    return segs

# Flange: an outline of four lobes (arcs R 12 round the bolt holes) joined by
# concave arcs R 20, four bolt holes of 8 mm, a centre bore of 30 mm. The
# bolt holes are cut with a 3 mm tool (T2), the bore and outline with 6 mm
# (T1): one tool number is one diameter.
def flange():
    segs=[]
    Rb=35  # bolt circle radius
    lobe=12
    # lobes at 45, 135, 225, 315 degrees; between them a concave fillet
    pts=[]
    ents=[]
    for k in range(4):
        a=math.radians(45+90*k)
        cx,cy=Rb*math.cos(a),Rb*math.sin(a)
        segs+=arc(cx,cy,lobe,a-math.radians(75),a+math.radians(75))
        # concave arc to the next lobe, centre further out on the bisector
        b=a+math.radians(45)
        nxt=a+math.radians(90)
        p_end=[cx+lobe*math.cos(a+math.radians(75)), cy+lobe*math.sin(a+math.radians(75))]
        q=[Rb*math.cos(nxt)+lobe*math.cos(nxt-math.radians(75)), Rb*math.sin(nxt)+lobe*math.sin(nxt-math.radians(75))]
        # concave: a cubic bezier bending inwards
        mid_in=[ (p_end[0]+q[0])/2*0.80, (p_end[1]+q[1])/2*0.80 ]
        t1=[-math.sin(a+math.radians(75)), math.cos(a+math.radians(75))]
        t2=[-math.sin(nxt-math.radians(75)), math.cos(nxt-math.radians(75))]
        L=8
        segs.append({"type":"bezier","points":[p_end,[p_end[0]+L*t1[0],p_end[1]+L*t1[1]],[q[0]-L*t2[0],q[1]-L*t2[1]],q]})
    join(segs)
    segs[-1]["points"][-1]=segs[0]["points"][0]
    outline={"id":"outline","type":"path","closed":True,"segments":segs,"side":"outside",
             "tabs":{"count":4,"width":4,"height":1.5}}
    for k in range(4):
        a=math.radians(45+90*k)
        h=circle(Rb*math.cos(a),Rb*math.sin(a),4)
        h.update({"id":"bolt-%d"%(k+1),"side":"inside","tool":2,"tool_diameter":3,"lead":{"radius":1.2,"length":0}})
        ents.append(h)
    bore=circle(0,0,15); bore.update({"id":"bore","side":"inside"})
    ents.append(bore)
    ents.append(outline)
    return {"bezcam":1,"units":"mm","tolerance":0.01,"order":"shortest",
            "job":{"feed":800,"plunge_feed":200,"safe_z":5,"top_z":0,"cut_z":-6,"step_down":2,"spindle_rpm":18000,
                   "tool":1,"tool_diameter":6,"direction":"climb","lead":{"radius":4,"length":2},
                   "tolerance_side":"waste"},
            "entities":ents}

# A cam profile (closed interpolating curve) with a notch narrower than the
# tool: the tool cannot follow it; the warning says where material is left.
def cam():
    pts=[]
    for k in range(24):
        a=2*math.pi*k/24
        r=30+8*math.cos(a)+3*math.cos(2*a)
        pts.append([round(r*math.cos(a),4), round(r*math.sin(a),4)])
    body={"type":"interpolate","through":pts,"closed":True}
    # The notch: a path replacing the profile near angle 90 degrees is
    # simpler as a separate path: a closed outline made of lines and the
    # cam's arc is complex, so the notch is a path of its own.
    segs=[]
    R=40
    a0,a1=math.radians(93),math.radians(447)
    segs+=arc(110,0,R,a0,a1)  # most of a circle, ccw, beside the cam
    p=segs[-1]["points"][-1]
    # notch about 4 mm wide (the tool is 8), 8 deep, at 90 degrees
    e=[110+R*math.cos(a0),R*math.sin(a0)]
    inward=lambda q,d:[110+(q[0]-110)*(R-d)/R,q[1]*(R-d)/R]
    segs.append(line(p, inward(p,8)))
    segs.append(line(inward(p,8), inward(e,8)))
    segs.append(line(inward(e,8), e))
    join(segs)
    segs[-1]["points"][-1]=segs[0]["points"][0]
    notch={"id":"notched-disc","type":"path","closed":True,"segments":segs,"side":"outside"}
    body.update({"id":"cam-profile","side":"outside"})
    return {"bezcam":1,"units":"mm","tolerance":0.01,
            "job":{"feed":1000,"plunge_feed":250,"safe_z":5,"top_z":0,"cut_z":-3,"step_down":1.5,"spindle_rpm":16000,
                   "tool":1,"tool_diameter":8,"lead":{"radius":5,"length":3}},
            "entities":[body,notch]}

# Lettering cut on the line (engraving): "S" and "C" as cubic paths, side on,
# the deviation only to the left of travel.
def lettering():
    S={"id":"S","type":"path","segments":join([
        {"type":"bezier","points":[[18,18],[14,22],[2,22],[2,15],]},
        {"type":"bezier","points":[[2,15],[2,9],[18,11],[18,5]]},
        {"type":"bezier","points":[[18,5],[18,-2],[4,-2],[1,3]]}])}
    C={"id":"C","type":"path","segments":join([
        {"type":"bezier","points":[[40,18],[36,23],[24,22],[24,10]]},
        {"type":"bezier","points":[[24,10],[24,-2],[36,-3],[40,2]]}])}
    return {"bezcam":1,"units":"mm","tolerance":0.01,
            "job":{"feed":600,"plunge_feed":100,"safe_z":3,"top_z":0,"cut_z":-0.4,"spindle_rpm":20000,"tool":3,
                   "side":"on","tolerance_side":"left"},
            "entities":[S,C]}

# The same flange cut with the controller's compensation (G41/G42 D-): the
# program carries the part's edge; each tool's diameter is in its D register.
def flange_g41():
    j=flange()
    j["job"].update({"compensation":"controller","lead":{"radius":4,"length":4}})
    for e in j["entities"]:
        if e.get("id","").startswith("bolt-"):
            e.update({"lead":{"radius":0.8,"length":1.6}})
    return j

# The same flange with a tool table instead of tool_diameter and step_down:
# a 6 mm bull nose (T1) whose 2.5 mm flutes split the 6 mm cut into three
# passes, a 3 mm flat end mill (T2) with 4 mm flutes, two passes, for the
# bolt holes.
def flange_tools():
    j=flange()
    j["tools"]={"1":{"shape":"bull","diameter":6,"corner_radius":0.5,"flute_length":2.5},
                "2":{"shape":"flat","diameter":3,"flute_length":4,"center_cutting":True},
                "3":{"shape":"vee","diameter":6,"angle":60}}
    del j["job"]["tool_diameter"]
    del j["job"]["step_down"]
    for e in j["entities"]:
        e.pop("tool_diameter",None)
    return j

# Plate: a 60 x 40 recess 4 deep cleared round two bosses of 12 mm, then
# the plate's outline (100 x 70, corners R 5) cut outside on four tabs; one
# 6 mm tool (docs/pocket.md).
def rounded_rect(x0,y0,x1,y1,R):
    s=[line([x0+R,y0],[x1-R,y0])]+arc(x1-R,y0+R,R,-math.pi/2,0)+[line([x1,y0+R],[x1,y1-R])]+arc(x1-R,y1-R,R,0,math.pi/2)
    s+=[line([x1-R,y1],[x0+R,y1])]+arc(x0+R,y1-R,R,math.pi/2,math.pi)+[line([x0,y1-R],[x0,y0+R])]+arc(x0+R,y0+R,R,math.pi,1.5*math.pi)
    s=join(s); s[-1]["points"][-1]=s[0]["points"][0]
    return {"type":"path","closed":True,"segments":s}
def plate():
    recess=dict(rounded_rect(20,15,80,55,4),id="recess")
    boss1=dict(circle(38,35,6),id="boss-1"); boss2=dict(circle(62,35,6),id="boss-2")
    for e in (recess,boss1,boss2):
        e.update({"operation":"pocket","region":"recess","cut_z":-4,"stepover":2.4})
    outline=dict(rounded_rect(0,0,100,70,5),id="outline")
    outline.update({"side":"outside","cut_z":-8,"lead":{"radius":4,"length":2},"tabs":{"count":4,"width":6,"height":2}})
    return {"bezcam":1,"units":"mm","tolerance":0.01,
            "job":{"feed":800,"plunge_feed":200,"safe_z":5,"top_z":0,"clearance":1,"step_down":2,"spindle_rpm":18000,
                   "tool":1,"tool_diameter":6,"direction":"climb","tolerance_side":"waste"},
            "entities":[recess,boss1,boss2,outline]}

# The plate with four holes of 5 mm through it, drilled in pecks of 3 mm
# (G83) between the recess and the outline: two drawn as points, two as
# circles. Three tools: the recess's 6 mm end mill (T1), a 5 mm drill (T2),
# an 8 mm end mill for the outline (T3) (docs/holes.md).
def plate_drilled():
    j=plate()
    j["tools"]={"1":{"shape":"flat","diameter":6,"center_cutting":True},
                "2":{"shape":"drill","diameter":5,"point_angle":118,"flute_length":30},
                "3":{"shape":"flat","diameter":8,"flute_length":20}}
    del j["job"]["tool_diameter"]
    holes=[]
    for k,(x,y) in enumerate([(8,8),(92,8),(92,62),(8,62)]):
        h={"type":"point","at":[x,y]} if k%2==0 else circle(x,y,2.5)
        h.update({"id":"hole-%d"%(k+1),"operation":"drill","tool":2,"cut_z":-8.5,"peck":3})
        holes.append(h)
    outline=j["entities"][-1]
    outline["tool"]=3
    j["entities"]=j["entities"][:-1]+holes+[outline]
    return j

# A smaller plate whose recess round one boss is cleared adaptively (the
# tool's engagement held to what load 1 gives: arccos(1 - 1/3) = 48 degrees),
# then the outline on tabs, one 6 mm tool (docs/pocket.md).
def plate_adaptive():
    recess=dict(rounded_rect(10,8,50,37,4),id="recess")
    boss=dict(circle(30,22.5,5),id="boss")
    for e in (recess,boss):
        e.update({"operation":"pocket","region":"recess","cut_z":-3,"pattern":"adaptive","load":1})
    outline=dict(rounded_rect(0,0,60,45,5),id="outline")
    outline.update({"side":"outside","cut_z":-6,"lead":{"radius":4,"length":2},"tabs":{"count":4,"width":6,"height":2}})
    return {"bezcam":1,"units":"mm","tolerance":0.01,
            "job":{"feed":800,"plunge_feed":200,"safe_z":5,"top_z":0,"clearance":1,"step_down":3,"spindle_rpm":18000,
                   "tool":1,"tool_diameter":6,"direction":"climb","tolerance_side":"waste"},
            "entities":[recess,boss,outline]}

for name,f in [("part-plate",plate),("part-plate-adaptive",plate_adaptive),("part-plate-drilled",plate_drilled),("controller-comp/flange-g41",flange_g41),("part-flange",flange),("part-flange-tools",flange_tools),("part-cam-notch",cam),("part-lettering",lettering)]:
    open("samples/%s.json"%name,"w").write(json.dumps(f(),indent=1)+"\n")
