package io.github.jdem846.cli;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.sun.Body;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.SunLightField;
import io.github.jdem846.sun.TwilightFade;
import io.github.jdem846.sun.ZonedTimeParser;
import java.io.PrintWriter;
import java.util.Locale;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * The light: {@code --sun-azimuth}/{@code --sun-elevation} (the original's defaults 320° and 25°), or the real sun
 * at {@code --sun-time}, seen from the DEM's centre, from {@code --sun-at}, or per tile.
 */
public final class SunOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    /** Not a number (NaN, ±Infinity) is bad usage like "abc" (exit 2); a number out of range fails later (exit 1). */
    Double azimuth;

    Double elevation;

    @Option(names = {"--sun-azimuth", "--azimuth"}, paramLabel = "DEG",
            description = "Sun azimuth, degrees clockwise from north (any value; reduced to [0, 360)). Default: 320.")
    void azimuth(double degrees) {
        if (!Double.isFinite(degrees)) {
            throw new ParameterException(command.commandLine(), "--sun-azimuth must be a finite number of degrees"
                    + " (any value, e.g. -720 or 250), got " + degrees);
        }
        azimuth = degrees;
    }

    @Option(names = {"--sun-elevation", "--altitude"}, paramLabel = "DEG",
            description = "Sun elevation above the horizon in degrees, -90..90 (≤ 0: no direct light). Default: 25.")
    void elevation(double degrees) {
        if (!Double.isFinite(degrees)) {
            throw new ParameterException(command.commandLine(), "--sun-elevation must be a number of degrees"
                    + " between -90 and 90, got " + degrees);
        }
        elevation = degrees;
    }

    @Option(names = "--sun-time", paramLabel = "TIME",
            description = "Compute the sun for this instant instead (ISO-8601 with offset or zone, e.g. "
                    + "2024-06-21T05:30+02:00 or 2024-06-21T05:30[Europe/Luxembourg]), seen from the DEM's centre.")
    String time;

    @Option(names = "--sun-at", paramLabel = "LAT,LON",
            description = "With --sun-time: the place to compute the sun for (needed when the DEM's CRS is unknown).")
    String place;

    @Option(names = "--sun-per-tile",
            description = "With --sun-time: recompute the sun for every tile from its own latitude/longitude.")
    boolean perTile;

    @Option(names = "--twilight",
            description = "With --sun-time: the original's twilight fade, darkening the scene linearly from zenith "
                    + "90° to 108° (civil to astronomical twilight).")
    boolean twilight;

    /** True when the sun is given by date and time. */
    boolean byTime() {
        return time != null;
    }

    /** The fixed light (azimuth/elevation options); refused together with --sun-time. */
    LightDirection fixedLight() {
        return new LightDirection(azimuth != null ? azimuth : 320, elevation != null ? elevation : 25);
    }

    /** The light over a grid and the darkening of the whole scene (twilight fade, 0 in daylight). */
    record Lighting(LightField field, double fade) {
    }

    /** The light over {@code grid} and the twilight darkening; prints the sun used on {@code err}. */
    Lighting light(GridGeometry grid, Body body, int tileSize, PrintWriter err) {
        if (time == null) {
            if (place != null || perTile || twilight) {
                throw new IllegalArgumentException("--sun-at, --sun-per-tile and --twilight need --sun-time");
            }
            return new Lighting(LightField.uniform(fixedLight()), 0);
        }
        if (azimuth != null || elevation != null) {
            throw new IllegalArgumentException("give either --sun-time or --sun-azimuth/--sun-elevation, not both");
        }
        body.requireSunByDateAndTime();
        LatLon at = place == null ? null : LatLon.parse(place);
        SunLightField field = SunLightField.of(grid, ZonedTimeParser.parse(time), at, perTile ? tileSize : 0,
                Observer.SEA_LEVEL);
        double fade = twilight ? TwilightFade.ORIGINAL.darkening(field.centralSun().zenithDegrees()) : 0;
        err.println(String.format(Locale.ROOT, "jdem846: sun at %s: azimuth %.2f°, elevation %.2f°%s", time,
                field.centralSun().azimuthDegrees(), field.centralSun().elevationDegrees(),
                field.centralSun().isBelowHorizon() ? " (below the horizon: no direct light)" : ""));
        err.flush();
        return new Lighting(field, fade);
    }
}
