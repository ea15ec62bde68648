/* raster.c -- unit tests of the rasterizer, images and colormaps */
#include "colormap.h"
#include "image.h"
#include "raster.h"
#include "tap.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int is_bg(const struct image *im, int x, int y, const unsigned char bg[3])
{
    return !memcmp(image_px(im, x, y), bg, 3);
}

/* an n x n grid of the unit square in the z = 0 plane, alternating diagonals */
static void grid(int n, double **V, int **F, int *nv, int *nf)
{
    *nv = (n + 1) * (n + 1);
    *nf = 2 * n * n;
    *V = malloc((size_t)*nv * 3 * sizeof **V);
    *F = malloc((size_t)*nf * 3 * sizeof **F);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double *p = *V + 3 * (j * (n + 1) + i);
            /* irregular spacing so edges cross samples at odd positions */
            p[0] = (double)i / n + (i > 0 && i < n ? 0.013 * ((i * 7 + j * 3) % 5 - 2) / n : 0);
            p[1] = (double)j / n + (j > 0 && j < n ? 0.011 * ((i * 5 + j * 11) % 7 - 3) / n : 0);
            p[2] = 0;
        }
    int k = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            int *f = *F + 3 * k;
            if ((i + j) % 2) { f[0] = a; f[1] = b; f[2] = c; f[3] = a; f[4] = c; f[5] = d; }
            else { f[0] = a; f[1] = b; f[2] = d; f[3] = b; f[4] = c; f[5] = d; }
            k += 2;
        }
}

int main(void)
{
    /* ---- rasterizer ---- */
    double *V;
    int *F, nv, nf;
    grid(23, &V, &F, &nv, &nf);
    struct camera cam;
    camera_init(&cam, 0, 0, 1);
    cam.margin = 0;
    camera_fit(&cam, V, nv);
    struct render_style st;
    render_style_default(&st);
    st.ss = 1;
    st.flat = 1;
    struct image im;
    ok(raster_render(V, F, nv, nf, &cam, &st, 89, 89, &im) == 0, "raster: renders a grid");
    int holes = 0;
    for (int y = 0; y < im.h; y++)
        for (int x = 0; x < im.w; x++) holes += is_bg(&im, x, y, st.background);
    ok(holes == 0, "raster: a grid filling the view leaves no sample uncovered (%d holes)", holes);
    image_free(&im);

    /* the front of the grid faces +z: bright from the front, dimmer from behind */
    camera_init(&cam, 180, 0, 1);
    camera_fit(&cam, V, nv);
    ok(raster_render(V, F, nv, nf, &cam, &st, 40, 40, &im) == 0, "raster: back view renders");
    unsigned char back = image_px(&im, 20, 20)[0];
    image_free(&im);
    camera_init(&cam, 0, 0, 1);
    camera_fit(&cam, V, nv);
    raster_render(V, F, nv, nf, &cam, &st, 40, 40, &im);
    unsigned char front = image_px(&im, 20, 20)[0];
    image_free(&im);
    ok(back < 0.7 * front && back > 0, "raster: two-sided lighting, back %d < front %d", back, front);

    /* orientation: a triangle in the +x,+y corner appears right and up */
    double T[9] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
    double Tb[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};   /* fit box */
    int TF[3] = {0, 1, 2};
    camera_init(&cam, 0, 0, 1);
    camera_fit(&cam, Tb, 4);
    raster_render(T, TF, 3, 1, &cam, &st, 40, 40, &im);
    ok(!is_bg(&im, 33, 12, st.background) && is_bg(&im, 6, 33, st.background) &&
       is_bg(&im, 6, 12, st.background), "camera: front view, +x right and +y up");
    image_free(&im);
    /* top view with y up: +x right, +z down; the triangle in the x,z plane */
    double Tz[9] = {0, 0, 0, 1, 0, 0, 1, 0, 1};
    double Tzb[12] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    camera_init(&cam, 0, 90, 1);
    camera_fit(&cam, Tzb, 4);
    raster_render(Tz, TF, 3, 1, &cam, &st, 40, 40, &im);
    ok(!is_bg(&im, 33, 28, st.background) && is_bg(&im, 33, 6, st.background),
       "camera: top view, +z towards the bottom of the image");
    image_free(&im);
    /* up = z: front view looks along +y, z is up */
    double Tu[9] = {0, 0, 0, 1, 0, 0, 1, 0, 1};
    camera_init(&cam, 0, 0, 2);
    camera_fit(&cam, Tzb, 4);
    raster_render(Tu, TF, 3, 1, &cam, &st, 40, 40, &im);
    ok(!is_bg(&im, 33, 12, st.background) && is_bg(&im, 33, 33, st.background),
       "camera: --up z puts +z at the top");
    image_free(&im);
    double az, el;
    ok(camera_named_view("iso", &az, &el) == 0 && az == 45 && el > 35 && el < 36 &&
       camera_named_view("sideways", &az, &el) < 0, "camera: named views");

    /* split vertices (UV seams) shade like welded ones; hard edges stay */
    for (int hard = 0; hard < 2; hard++) {
        double hgt = hard ? 1.5 : 0.25;   /* ridge height: 53 or 113 degrees between sides */
        /* a tent over [-1,1]x[0,1]: ridge along y at x = 0 */
        double Vw[18] = {-1, 0, 0, 0, 0, hgt, 1, 0, 0, -1, 1, 0, 0, 1, hgt, 1, 1, 0};
        int Fw[12] = {0, 1, 4, 0, 4, 3, 2, 5, 4, 2, 4, 1};   /* mirror-symmetric */
        double Vs[24] = {-1, 0, 0, 0, 0, hgt, 1, 0, 0, -1, 1, 0, 0, 1, hgt, 1, 1, 0,
                         0, 0, hgt, 0, 1, hgt};   /* 6, 7: copies of the ridge for the right side */
        int Fs[12] = {0, 1, 4, 0, 4, 3, 2, 5, 7, 2, 7, 6};
        struct render_style sm;
        render_style_default(&sm);
        struct camera c2;
        camera_init(&c2, 20, 30, 1);
        camera_fit(&c2, Vw, 6);
        struct image iw, is;
        raster_render(Vw, Fw, 6, 4, &c2, &sm, 60, 60, &iw);
        raster_render(Vs, Fs, 8, 4, &c2, &sm, 60, 60, &is);
        int same = !memcmp(iw.rgb, is.rgb, (size_t)60 * 60 * 3);
        if (!hard)
            ok(same, "raster: vertices split along a seam shade like welded ones");
        else
            ok(!same, "raster: a hard edge (113 degrees) made of split vertices stays sharp");
        image_free(&iw);
        image_free(&is);
    }

    /* ---- images ---- */
    unsigned char bg[3] = {10, 20, 30}, fg[3] = {250, 240, 230};
    struct image a;
    ok(image_alloc(&a, 37, 23, bg) == 0 && !memcmp(image_px(&a, 36, 22), bg, 3),
       "image: alloc fills the background");
    image_text(&a, 2, 2, "42 ok", 2, fg, NULL);
    int lit = 0;
    for (int y = 0; y < a.h; y++)
        for (int x = 0; x < a.w; x++) lit += !memcmp(image_px(&a, x, y), fg, 3);
    ok(lit > 40 && text_width("42 ok", 2) == 2 * (5 * 6 - 1) && text_height(3) == 21,
       "image: text draws pixels (%d) and measures", lit);
    char png[] = "/tmp/stopmo-unit-XXXXXX";
    int fd = mkstemp(png);
    FILE *f = fdopen(fd, "wb");
    ok(image_write_png(f, &a) == 0 && fclose(f) == 0, "image: PNG written");
    struct image b;
    ok(image_read(png, &b) == 0 && b.w == a.w && b.h == a.h &&
       !memcmp(a.rgb, b.rgb, (size_t)a.w * a.h * 3), "image: PNG reads back identical");
    image_free(&b);
    f = fopen(png, "wb");
    ok(image_write_ppm(f, &a) == 0 && fclose(f) == 0 && image_read(png, &b) == 0 &&
       !memcmp(a.rgb, b.rgb, (size_t)a.w * a.h * 3), "image: PPM reads back identical");
    image_free(&b);
    unlink(png);
    struct image tiles[3] = {a, a, {0, 0, NULL}}, g;
    ok(image_grid(tiles, 3, 2, 3, fg, &g) == 0 && g.w == 2 * 37 + 3 * 3 && g.h == 2 * 23 + 3 * 3,
       "image: grid size");
    image_free(&g);
    image_free(&a);
    int w, h;
    ok(image_parse_size("640x480", &w, &h) == 0 && w == 640 && h == 480 &&
       image_parse_size("0x4", &w, &h) < 0 && image_parse_size("4x", &w, &h) < 0 &&
       image_parse_size("4x4x4", &w, &h) < 0 && image_parse_size("-4x4", &w, &h) < 0,
       "image: size parsing");

    /* ---- colormaps ---- */
    static unsigned char c[256][3];
    int d64 = 999, d256 = 999;
    for (int i = 0; i < 256; i++) {
        colormap_label(i, c[i]);
        for (int j = 0; j < i; j++) {
            int d = abs(c[i][0] - c[j][0]) + abs(c[i][1] - c[j][1]) + abs(c[i][2] - c[j][2]);
            if (i < 64 && d < d64) d64 = d;
            if (d < d256) d256 = d;
        }
    }
    ok(d64 >= 40 && d256 >= 20, "colormap: labels are distinct (closest pair, L1 in RGB: "
       "%d among 0..63, %d among 0..255)", d64, d256);
    unsigned char grey[3];
    colormap_label(-1, grey);
    ok(grey[0] == grey[1] && grey[1] == grey[2], "colormap: label -1 is grey");
    unsigned char v0[3], v1[3];
    colormap_viridis(0, v0);
    colormap_viridis(1, v1);
    ok(abs(v0[0] - 0x44) <= 4 && abs(v0[1] - 0x01) <= 4 && abs(v0[2] - 0x54) <= 4 &&
       abs(v1[0] - 0xfd) <= 4 && abs(v1[1] - 0xe7) <= 4 && abs(v1[2] - 0x25) <= 4,
       "colormap: viridis ends are #440154 and #fde725");
    ok(colormap_t(5, 0, 10) == 0.5 && colormap_t(-1, 0, 10) == 0 && colormap_t(3, 2, 2) == 0.5,
       "colormap: scalar position, clamped");
    unsigned char p[3];
    ok(color_parse("1,2,3", p) == 0 && p[2] == 3 && color_parse("#ff8000", p) == 0 && p[1] == 0x80 &&
       color_parse("1,2", p) < 0 && color_parse("1,2,300", p) < 0 && color_parse("#ff80", p) < 0 &&
       color_parse("white", p) == 0 && p[0] == 255, "colormap: colour parsing");
    free(V);
    free(F);
    return tap_done();
}
