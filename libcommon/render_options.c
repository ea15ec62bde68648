/* render_options.c -- see render_options.h (program harness, tools only). */
#include "render_options.h"
#include "colormap.h"
#include "image.h"
#include "tool.h"
#include <stdlib.h>
#include <string.h>

void render_options_init(struct render_options *ro)
{
    struct render_style def;
    render_style_default(&def);
    memset(ro, 0, sizeof *ro);
    ro->view = "front";
    ro->up = 1;
    ro->fov = 30;
    ro->ss = def.ss;
    memcpy(ro->color, def.color, 3);
    memcpy(ro->background, def.background, 3);
}

static int parse_axis(const char *s)
{
    static const char *names[] = {"x", "y", "z", "-x", "-y", "-z"};
    for (int i = 0; i < 6; i++)
        if (!strcmp(s, names[i]) || (i < 3 && s[0] == '+' && !strcmp(s + 1, names[i])))
            return i;
    usage_error("--up: '%s' is not x, y, z, -x, -y or -z", s);
}

int render_options_parse(struct render_options *ro, int c, const char *arg)
{
    switch (c) {
    case 'V': ro->view = arg; break;
    case 'a': ro->azimuth = arg_double(arg, "--azimuth"); ro->have_az = 1; break;
    case 'e': ro->elevation = arg_double(arg, "--elevation"); ro->have_el = 1; break;
    case RO_UP: ro->up = parse_axis(arg); break;
    case RO_PERSP: ro->perspective = 1; break;
    case RO_FOV: ro->fov = arg_double(arg, "--fov"); break;
    case 'l': ro->labels = arg; break;
    case RO_SCALARS: ro->scalars = arg; break;
    case RO_RANGE: {
        char *end;
        ro->range[0] = strtod(arg, &end);
        if (end == arg || *end != ',')
            usage_error("--range: '%s' is not MIN,MAX", arg);
        ro->range[1] = arg_double(end + 1, "--range");
        if (!(ro->range[1] > ro->range[0]))
            usage_error("--range: MAX must be greater than MIN");
        ro->have_range = 1;
        break;
    }
    case 'w': ro->wireframe = 1; break;
    case RO_FLAT: ro->flat = 1; break;
    case 'c':
        if (color_parse(arg, ro->color) < 0)
            usage_error("--color: '%s' is not R,G,B (0..255) or #rrggbb", arg);
        break;
    case 'b':
        if (color_parse(arg, ro->background) < 0)
            usage_error("--background: '%s' is not R,G,B (0..255) or #rrggbb", arg);
        break;
    case RO_SS: ro->ss = (int)arg_long(arg, "--supersample"); break;
    case 'f': ro->format = arg; break;
    case 'o': ro->output = arg; break;
    case RO_COMPACT: image_png_small(1); break;
    default: return 0;
    }
    return 1;
}

void render_options_check(struct render_options *ro)
{
    double az = ro->azimuth, el = ro->elevation;
    if (camera_named_view(ro->view, &ro->azimuth, &ro->elevation) < 0)
        usage_error("unknown view '%s' (front, back, left, right, top, bottom, iso)", ro->view);
    if (ro->have_az) ro->azimuth = az;
    if (ro->have_el) ro->elevation = el;
    if (ro->elevation < -90 || ro->elevation > 90)
        usage_error("--elevation must be in -90..90");
    if (!(ro->fov > 1 && ro->fov < 170))
        usage_error("--fov must be in 1..170 degrees");
    if (ro->ss < 1 || ro->ss > 8)
        usage_error("--supersample must be in 1..8");
    if (ro->labels && ro->scalars)
        usage_error("--labels and --scalars exclude each other");
    if (ro->have_range && !ro->scalars)
        usage_error("--range needs --scalars");
}

void render_options_format(struct render_options *ro, const char *path)
{
    if (!ro->format) {
        const char *dot = path ? strrchr(path, '.') : NULL;
        ro->format = dot && (!strcmp(dot, ".ppm") || !strcmp(dot, ".pnm")) ? "ppm" : "png";
    }
    if (strcmp(ro->format, "png") && strcmp(ro->format, "ppm"))
        usage_error("--format: '%s' is not png or ppm", ro->format);
}

void render_options_camera(const struct render_options *ro, struct camera *cam)
{
    camera_init(cam, ro->azimuth, ro->elevation, ro->up);
    cam->perspective = ro->perspective;
    cam->fov = ro->fov;
}

void render_options_style(const struct render_options *ro, struct render_style *st)
{
    render_style_default(st);
    memcpy(st->color, ro->color, 3);
    memcpy(st->background, ro->background, 3);
    st->wireframe = ro->wireframe;
    st->flat = ro->flat;
    st->ss = ro->ss;
}
