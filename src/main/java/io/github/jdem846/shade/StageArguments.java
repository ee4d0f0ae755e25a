package io.github.jdem846.shade;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.util.Objects;

/** The argument checks every {@link IlluminationStage} makes, with messages for a person. */
final class StageArguments {

    private StageArguments() {
    }

    static void check(Dem dem, LightDirection light, int col0, int row0, int w, int h, float[] out) {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(light, "light");
        Objects.requireNonNull(out, "out");
        if (w < 1 || h < 1 || col0 < 0 || row0 < 0 || (long) col0 + w > dem.width()
                || (long) row0 + h > dem.height()) {
            throw new IllegalArgumentException("rectangle " + w + "×" + h + " at column " + col0 + ", row " + row0
                    + " must lie inside the " + dem.width() + "×" + dem.height() + " DEM");
        }
        if (out.length < (long) w * h) {
            throw new IllegalArgumentException("output array holds " + out.length + " values; the " + w + "×" + h
                    + " rectangle needs " + (long) w * h);
        }
    }
}
