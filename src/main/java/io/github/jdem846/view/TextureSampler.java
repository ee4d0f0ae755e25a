package io.github.jdem846.view;

import io.github.jdem846.render.RenderedRelief;

/**
 * Bilinear lookups in a relief picture at positions in its pixels (pixel centres at whole numbers), clamped to its
 * edges; transparent (no-data) pixels do not count, so a hole's edge keeps its neighbours' colours.
 */
final class TextureSampler {

    private final int[] argb;
    private final int width;
    private final int height;

    TextureSampler(RenderedRelief picture) {
        this.argb = picture.argb();
        this.width = picture.width();
        this.height = picture.height();
    }

    /** The opaque colour at ({@code u}, {@code v}), or 0 when only transparent pixels are near. */
    int at(float u, float v) {
        double x = Math.max(0, Math.min(width - 1, u));
        double y = Math.max(0, Math.min(height - 1, v));
        int x0 = (int) Math.floor(x);
        int y0 = (int) Math.floor(y);
        int x1 = Math.min(width - 1, x0 + 1);
        int y1 = Math.min(height - 1, y0 + 1);
        double fx = x - x0;
        double fy = y - y0;
        double r = 0;
        double g = 0;
        double b = 0;
        double weight = 0;
        int[] pixels = {argb[y0 * width + x0], argb[y0 * width + x1], argb[y1 * width + x0], argb[y1 * width + x1]};
        double[] weights = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        for (int k = 0; k < 4; k++) {
            double wa = weights[k] * (pixels[k] >>> 24);
            r += wa * ((pixels[k] >> 16) & 255);
            g += wa * ((pixels[k] >> 8) & 255);
            b += wa * (pixels[k] & 255);
            weight += wa;
        }
        if (!(weight > 1e-6)) {
            return 0;
        }
        return 0xFF000000 | (int) Math.round(r / weight) << 16 | (int) Math.round(g / weight) << 8
                | (int) Math.round(b / weight);
    }
}
