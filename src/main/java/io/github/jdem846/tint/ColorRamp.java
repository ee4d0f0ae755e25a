package io.github.jdem846.tint;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * An elevation tint (hypsometric/bathymetric tinting, the article's section 2) as an immutable value: colour stops
 * by percent of a DEM's range (eq. 1–3) or by elevation. {@link #bind} fixes the range of one DEM and gives the
 * fast {@link TintFunction} that the renderer calls per cell.
 *
 * <p>Get one by name ({@link #named}: {@code hypsometric-bathymetric}, the default, {@code hypsometric},
 * {@code etopo1}, {@code standard}, …), from a {@code gdaldem color-relief} colour file ({@link #fromGdalColorFile}),
 * or build a {@link StopRamp} from {@link ColorStop}s.
 *
 * <pre>{@code
 * TintFunction tint = ColorRamp.named("hypsometric").bind(dem.statistics());
 * int argb = tint.argb(dem.get(col, row));
 * }</pre>
 */
public sealed interface ColorRamp permits StopRamp, SeaLandRamp, TopoBathyRamp, ScaledRamp {

    /**
     * The name of the default ramp, {@code hypsometric-bathymetric}: the article's table 2 ({@code hypsometric})
     * over [min, max], or, for a DEM holding both land and sea (min &lt; 0 &lt; max), table 2 over [0, max] and the
     * original's {@code bathymetric} over [min, 0] (a {@link TopoBathyRamp}).
     */
    String DEFAULT_NAME = "hypsometric-bathymetric";

    /** {@return a short name for messages (the built-in name, or the colour file's name)} */
    String name();

    /**
     * This ramp for a DEM whose valid elevations span {@code range} (min/max from {@link Dem#statistics()}): the
     * percent stops are fixed against [min, max]; absolute stops ignore the range.
     *
     * <p>Elevations beyond the end stops take the end colours; NaN (no-data) gives the ramp's no-data colour
     * (transparent unless a colour file names one with {@code nv}). A flat DEM (max = min) is coloured as if every
     * cell were at 0 %. A range with no valid cells binds as the flat range [0, 0].
     *
     * @throws IllegalArgumentException if the ramp has percent stops and the range is not finite (a DEM holding
     *                                  ±∞, usually an undeclared no-data value)
     * @param range the DEM's valid elevations
     * @return the tint of each elevation
     */
    TintFunction bind(ElevationStatistics range);

    /**
     * {@code bind(dem.statistics())}.
     *
     * @param dem the DEM to colour
     * @return the tint of each elevation
     */
    default TintFunction bind(Dem dem) {
        return bind(dem.statistics());
    }

    /**
     * This ramp with its range spread by {@code scale} (the original's elevation scalers), for ramps in percent of
     * the range; see {@link ScaledRamp}.
     *
     * @param scale how the range is spread over the stops
     * @return this ramp itself for {@link TintScale#LINEAR}, else the scaled ramp
     * @throws IllegalArgumentException if the ramp places colours at fixed elevations (etopo1, dark-bathymetric, a
     *                                  colour file in metres) or is already scaled
     */
    default ColorRamp withScale(TintScale scale) {
        return scale == TintScale.LINEAR ? this : new ScaledRamp(this, scale);
    }

    /**
     * A built-in ramp by name, case-insensitive ({@code _} and spaces count as {@code -}); the original jDem846
     * identifiers ({@code hypsometric-tint}, {@code standard-coloring}, …) are accepted as aliases.
     *
     * @param name a built-in name, e.g. {@code hypsometric} or {@code etopo1}
     * @return the ramp
     * @throws IllegalArgumentException for an unknown name; the message lists the known names
     */
    static ColorRamp named(String name) {
        return BuiltInRamps.named(name);
    }

    /** {@return the names of the built-in ramps, default first} */
    static List<String> names() {
        return BuiltInRamps.names();
    }

    /** {@return the default ramp, {@code hypsometric-bathymetric} (see {@link #DEFAULT_NAME})} */
    static ColorRamp defaultRamp() {
        return named(DEFAULT_NAME);
    }

    /**
     * Reads a {@code gdaldem color-relief} colour file: lines {@code value R G B [A]} or {@code value colourname [A]},
     * where value is an elevation, {@code N%} of the DEM's range or {@code nv} (the no-data colour); {@code #} and
     * {@code /} start comment lines; fields are separated by spaces, tabs, commas or colons. GMT {@code .cpt}
     * files with {@code # COLOR_MODEL = RGB} are read as gdaldem reads them. See docs/tint.md.
     *
     * @param file      the colour file
     * @param selection how colours between stops are chosen (gdaldem's default is {@link ColorSelection#INTERPOLATE})
     * @return the ramp the file describes
     * @throws ColorFileException naming the file, the line and what is wrong, for a file gdaldem would reject or
     *                            misread
     * @throws IOException        if the file cannot be read
     */
    static StopRamp fromGdalColorFile(Path file, ColorSelection selection) throws IOException {
        return GdalColorFile.read(file, selection);
    }
}
