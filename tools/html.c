/* tools/html.c: the web page of html.h. */
#include "html.h"

#include <stdio.h>
#include <string.h>

#include "textio.h"

int html_options(const char *cmd, const char *html)
{
    if (html && (!*html || strcmp(html, "-") == 0)) {
        fprintf(stderr, "garotor %s: --html needs a file name\n", cmd);
        return -1;
    }
    return 0;
}

/* one frame as [ox, oy, oz, xx, xy, xz, yx, yy, yz, zx, zy, zz] */
static void frame(FILE *f, ga_mat4 m)
{
    const int idx[12] = {3, 7, 11, 0, 4, 8, 1, 5, 9, 2, 6, 10};
    fputc('[', f);
    for (int i = 0; i < 12; i++) fprintf(f, "%s%.9g", i ? "," : "", m.m[idx[i]]);
    fputc(']', f);
}

/* JSON string contents: the titles and labels here are plain text */
static void jstr(FILE *f, const char *s)
{
    fputc('"', f);
    for (; s && *s; s++) {
        if (*s == '"' || *s == '\\' || *s == '<')
            fprintf(f, "\\u%04x", (unsigned char)*s);
        else if ((unsigned char)*s >= 0x20)
            fputc(*s, f);
    }
    fputc('"', f);
}

/* The script: fit the scene, project it from (azimuth, elevation), draw paths
   back to front is not needed for lines; drag to turn. */
static const char *script =
    "window.onerror=function(m){document.body.setAttribute('data-error',String(m));};\n"
    "(function(){\n"
    "var c=document.getElementById('c'),g=c.getContext('2d');\n"
    "var pts=[];S.keys.forEach(function(k){pts.push(k.slice(0,3));});\n"
    "S.paths.forEach(function(p){p.m.forEach(function(k){pts.push(k.slice(0,3));});});\n"
    "var lo=[1e300,1e300,1e300],hi=[-1e300,-1e300,-1e300];\n"
    "pts.forEach(function(p){for(var "
    "i=0;i<3;i++){lo[i]=Math.min(lo[i],p[i]);hi[i]=Math.max(hi[i],p[i]);}});\n"
    "var mid=[0,1,2].map(function(i){return (lo[i]+hi[i])/2;});\n"
    "var rad=Math.max(1e-9,Math.hypot(hi[0]-lo[0],hi[1]-lo[1],hi[2]-lo[2])/2),fl=0.12*rad;\n"
    "var az=0.8,el=0.5,zoom=1,drag=null;\n"
    "function P(p){var x=p[0]-mid[0],y=p[1]-mid[1],z=p[2]-mid[2];\n"
    " var u=Math.cos(az)*x-Math.sin(az)*y,v=Math.sin(az)*x+Math.cos(az)*y;\n"
    " var w=Math.cos(el)*z-Math.sin(el)*v;var s=0.42*zoom*Math.min(c.width,c.height)/rad;\n"
    " return [c.width/2+s*u,c.height/2-s*w];}\n"
    "function seg(a,b,col,wd){var p=P(a),q=P(b);g.strokeStyle=col;g.lineWidth=wd;g.beginPath();"
    "g.moveTo(p[0],p[1]);g.lineTo(q[0],q[1]);g.stroke();}\n"
    "function fr(k,len,wd){var o=k.slice(0,3);['#d62728','#2ca02c','#1f77b4'].forEach(function(col,j){\n"
    " var a=k.slice(3+3*j,6+3*j);seg(o,[o[0]+len*a[0],o[1]+len*a[1],o[2]+len*a[2]],col,wd);});}\n"
    "function draw(){g.fillStyle='#ffffff';g.fillRect(0,0,c.width,c.height);\n"
    " seg([mid[0]-rad,mid[1],mid[2]],[mid[0]+rad,mid[1],mid[2]],'#dddddd',1);\n"
    " seg([mid[0],mid[1]-rad,mid[2]],[mid[0],mid[1]+rad,mid[2]],'#dddddd',1);\n"
    " seg([mid[0],mid[1],mid[2]-rad],[mid[0],mid[1],mid[2]+rad],'#dddddd',1);\n"
    " g.fillStyle='#888';g.font='13px sans-serif';[['x',0],['y',1],['z',2]].forEach(function(a){var "
    "e=mid.slice();e[a[1]]+=rad;var q=P(e);g.fillText(a[0],q[0]+4,q[1]-4);});\n"
    " S.paths.forEach(function(p){g.strokeStyle=p.colour;g.lineWidth=2;g.beginPath();\n"
    "  p.m.forEach(function(k,i){var q=P(k);if(i)g.lineTo(q[0],q[1]);else "
    "g.moveTo(q[0],q[1]);});g.stroke();\n"
    "  var step=Math.max(1,Math.floor(p.m.length/Math.max(1,p.frames)));\n"
    "  if(p.frames)for(var i=0;i<p.m.length;i+=step)fr(p.m[i],fl*0.6,1);});\n"
    " S.keys.forEach(function(k){fr(k,fl,3);var q=P(k);g.fillStyle='#000';g.beginPath();"
    "g.arc(q[0],q[1],4,0,7);g.fill();});\n"
    " g.fillStyle='#000';g.font='14px sans-serif';g.fillText(S.title,10,20);\n"
    " S.paths.forEach(function(p,i){g.fillStyle=p.colour;g.fillRect(10,34+16*i,16,3);g.fillStyle='#000';"
    "g.font='12px sans-serif';g.fillText(p.label,32,39+16*i);});\n"
    " document.body.setAttribute('data-state','drawn');}\n"
    "c.onmousedown=function(e){drag=[e.clientX,e.clientY];};\n"
    "window.onmouseup=function(){drag=null;};\n"
    "window.onmousemove=function(e){if(!drag)return;az+=0.01*(e.clientX-drag[0]);\n"
    " el=Math.max(-1.55,Math.min(1.55,el+0.01*(e.clientY-drag[1])));drag=[e.clientX,e.clientY];draw();};\n"
    "c.onwheel=function(e){zoom=Math.max(0.1,Math.min(20,zoom*Math.exp(-0.0015*e.deltaY)));e.preventDefault()"
    ";draw();};\n"
    "c.onkeydown=function(e){var k=e.key;if(k==='ArrowLeft')az-=0.1;else if(k==='ArrowRight')az+=0.1;\n"
    " else if(k==='ArrowUp')el=Math.min(1.55,el+0.1);else if(k==='ArrowDown')el=Math.max(-1.55,el-0.1);\n"
    " else if(k==='+'||k==='=')zoom*=1.2;else if(k==='-')zoom/=1.2;else if(k==='0'){az=0.8;el=0.5;zoom=1;}\n"
    " else return;e.preventDefault();draw();};\n"
    "draw();})();\n";

int html_write(tio_out *out, const char *file, const svg_picture *pic)
{
    if (tio_out_open(out, file))
        return -1;
    FILE *f = out->fp;
    fprintf(f, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>garotor</title>\n"
               "<style>body{margin:0;font-family:sans-serif}canvas{display:block;cursor:grab}</style>\n"
               "</head><body>\n<canvas id=\"c\" width=\"800\" height=\"560\" tabindex=\"0\"></canvas>\n"
               "<p style=\"margin:4px 10px\">Drag to turn, the wheel zooms; with the picture focused (Tab) "
               "the arrow keys turn, + and - zoom, 0 resets. Frames: x red, y green, z blue; "
               "keys bold with a dot.</p>\n<script>\nvar S={\"title\":");
    jstr(f, pic->title);
    fprintf(f, ",\n\"keys\":[");
    for (size_t i = 0; i < pic->nkeys; i++) {
        fprintf(f, i ? ",\n" : "\n");
        frame(f, pic->key[i]);
    }
    fprintf(f, "],\n\"paths\":[");
    for (size_t p = 0; p < pic->npaths; p++) {
        const svg_path *sp = &pic->path[p];
        fprintf(f, "%s{\"label\":", p ? ",\n" : "\n");
        jstr(f, sp->label);
        fprintf(f, ",\"colour\":");
        jstr(f, sp->colour);
        fprintf(f, ",\"frames\":%d,\"m\":[", sp->frames);
        for (size_t k = 0; k < sp->n; k++) {
            fprintf(f, k ? ",\n" : "\n");
            frame(f, sp->sample[k]);
        }
        fprintf(f, "]}");
    }
    fprintf(f, "]};\n%s</script>\n</body></html>\n", script);
    return tio_out_finish(out);
}
