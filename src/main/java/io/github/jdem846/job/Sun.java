package io.github.jdem846.job;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.SunLightField;
import io.github.jdem846.sun.TwilightFade;
import java.time.ZonedDateTime;
import java.util.Objects;

/**
 * Where the light comes from: a fixed direction, or the real sun at a date and time seen from the grid's centre
 * (or from {@code place}, or from every tile), optionally with the original's twilight fade. Immutable.
 *
 * @param direction the fixed light, or {@code null} when the sun is given by {@code time}
 * @param time      the instant, or {@code null} for a fixed light
 * @param place     with a time: where to compute the sun when the DEM's CRS cannot say, or {@code null}
 * @param perTile   with a time: a sun for every tile from its own latitude/longitude
 * @param twilight  with a time: darken the scene from zenith 90° to 108° (the original's twilight fade)
 */
public record Sun(LightDirection direction, ZonedDateTime time, LatLon place, boolean perTile, boolean twilight) {

    /** The original's light: azimuth 320°, elevation 25°. */
    public static final Sun ORIGINAL_DEFAULT = fixed(LightDirection.ORIGINAL_DEFAULT);

    /**
     * Checks that exactly one of direction and time is given, and that a place, a sun per tile and the twilight fade
     * come with a time.
     *
     * @param direction the fixed light, or {@code null} when the sun is given by {@code time}
     * @param time the instant, or {@code null} for a fixed light
     * @param place with a time: where to compute the sun when the DEM's CRS cannot say, or {@code null}
     * @param perTile with a time: a sun for every tile from its own latitude/longitude
     * @param twilight with a time: darken the scene from zenith 90° to 108° (the original's twilight fade)
     */
    public Sun {
        if ((direction == null) == (time == null)) {
            throw new IllegalArgumentException("give either a fixed light direction or a date and time, not both");
        }
        if (time == null && (place != null || perTile || twilight)) {
            throw new IllegalArgumentException("a place, a sun per tile and the twilight fade need a date and time");
        }
    }

    /**
     * A fixed light.
     *
     * @param direction where the light comes from
     * @return the sun
     */
    public static Sun fixed(LightDirection direction) {
        return new Sun(Objects.requireNonNull(direction, "direction"), null, null, false, false);
    }

    /**
     * A fixed light.
     *
     * @param azimuth   degrees clockwise from north
     * @param elevation degrees above the horizon
     * @return the sun
     */
    public static Sun fixed(double azimuth, double elevation) {
        return fixed(new LightDirection(azimuth, elevation));
    }

    /**
     * The real sun, seen from the centre of the grid.
     *
     * @param time the date and time, with its zone or offset
     * @return the sun
     */
    public static Sun at(ZonedDateTime time) {
        return new Sun(null, Objects.requireNonNull(time, "time"), null, false, false);
    }

    /**
     * The same sun seen from another place.
     *
     * @param where the latitude and longitude (for a DEM whose CRS is unknown)
     * @return the new sun
     */
    public Sun seenFrom(LatLon where) {
        return new Sun(direction, time, where, perTile, twilight);
    }

    /**
     * The same sun, computed or not for every tile from its own latitude and longitude.
     *
     * @param value true for a sun per tile
     * @return the new sun
     */
    public Sun perTile(boolean value) {
        return new Sun(direction, time, place, value, twilight);
    }

    /**
     * The same sun with or without the original's twilight fade.
     *
     * @param value true to darken the scene from zenith 90° to 108°
     * @return the new sun
     */
    public Sun withTwilight(boolean value) {
        return new Sun(direction, time, place, perTile, value);
    }

    /** {@return true when the sun is given by date and time} */
    public boolean byTime() {
        return time != null;
    }

    /**
     * The light over a grid and the darkening of the whole scene.
     *
     * @param field the light, uniform or per tile
     * @param fade  extra darkening in [0, 2] (the twilight fade; 0 in daylight or for a fixed light)
     * @param sun   the sun by date and time at the grid's centre, or {@code null} for a fixed light
     */
    record Lighting(LightField field, double fade, io.github.jdem846.sun.SunPosition sun) {

        /**
         * The same light over a grid in which the picture it was computed for starts at column {@code col}, row
         * {@code row} (a grid read with a halo, or a tile's piece of the picture and its halo).
         */
        Lighting inGrid(int col, int row) {
            return col == 0 && row == 0 ? this : new Lighting(new ShiftedLightField(field, col, row), fade, sun);
        }
    }

    /**
     * The light over {@code grid} (the picture: the sun by date and time is computed for its cells, whatever grid
     * is read around it), with tiles of {@code tileSize} cells from its north-west corner for a sun per tile.
     */
    Lighting over(GridGeometry grid, io.github.jdem846.sun.Body body, int tileSize) {
        if (time == null) {
            return new Lighting(LightField.uniform(direction), 0, null);
        }
        body.requireSunByDateAndTime();
        SunLightField field = SunLightField.of(grid, time, place, perTile ? tileSize : 0, Observer.SEA_LEVEL);
        double fade = twilight ? TwilightFade.ORIGINAL.darkening(field.centralSun().zenithDegrees()) : 0;
        return new Lighting(field, fade, field.centralSun());
    }

    /**
     * The light's central direction over {@code grid}, before the grid is read (to size the cast-shadow halo from
     * the file's header): the sun of the whole file, which differs from a window's by far less than the halo's
     * margin.
     */
    LightDirection centralOver(GridGeometry grid, io.github.jdem846.sun.Body body) {
        if (time == null) {
            return direction;
        }
        body.requireSunByDateAndTime();
        return SunLightField.of(grid, time, place, 0, Observer.SEA_LEVEL).central();
    }
}
