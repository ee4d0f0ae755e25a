package io.github.jdem846.geo;

import java.util.Locale;

/**
 * A position in degrees, north and east positive, on the CRS's own geodetic datum (no datum shift is applied).
 * The record itself accepts any numbers (a geographic grid may run 0–360° east); {@link #validated} and
 * {@link #parse} check the standard ranges.
 *
 * @param latitude  degrees north
 * @param longitude degrees east
 */
public record LatLon(double latitude, double longitude) {

    /**
     * A place for date-and-time sun positions: latitude in [−90, 90] and longitude in [−180, 180], with a message
     * for a person otherwise.
     *
     * @param latitude degrees north
     * @param longitude degrees east
     * @return the place
     */
    public static LatLon validated(double latitude, double longitude) {
        if (!(latitude >= -90 && latitude <= 90)) {
            throw new IllegalArgumentException("latitude must be between -90 and 90 degrees, got " + latitude);
        }
        if (!(longitude >= -180 && longitude <= 180)) {
            throw new IllegalArgumentException("longitude must be between -180 and 180 degrees, got " + longitude
                    + (Double.isFinite(longitude) ? " (wrap it, e.g. " + wrapLongitude(longitude) + ")" : ""));
        }
        return new LatLon(latitude, longitude);
    }

    /**
     * Parses {@code "LAT,LON"} in decimal degrees, e.g. {@code "49.61,6.13"} or {@code "-33.92, 18.42"}.
     *
     * @param text the text, e.g. {@code "49.61,6.13"}
     * @return the place, validated as by {@link #validated}
     * @throws IllegalArgumentException with a message naming the problem and the expected form
     */
    public static LatLon parse(String text) {
        String expected = "expected LAT,LON in decimal degrees (north and east positive), e.g. 49.61,6.13";
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("no place given; " + expected);
        }
        String[] parts = text.split(",", -1);
        if (parts.length != 2) {
            throw new IllegalArgumentException("'" + text + "' is not a place: " + expected);
        }
        double lat = number(parts[0], "latitude", text, expected);
        double lon = number(parts[1], "longitude", text, expected);
        return validated(lat, lon);
    }

    private static double number(String part, String what, String text, String expected) {
        String s = part.strip();
        try {
            double v = Double.parseDouble(s);
            if (!Double.isFinite(v) || s.endsWith("d") || s.endsWith("D") || s.endsWith("f") || s.endsWith("F")) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("the " + what + " '" + s + "' in '" + text + "' is not a number; "
                    + expected);
        }
    }

    /**
     * {@code longitude} reduced into [−180, 180).
     *
     * @param longitude degrees east, finite
     * @return the same meridian in [−180, 180)
     */
    public static double wrapLongitude(double longitude) {
        double l = (longitude + 180) % 360;
        if (l < 0) {
            l += 360;
        }
        return l - 180;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%.6f %s, %.6f %s", Math.abs(latitude), latitude < 0 ? "S" : "N",
                Math.abs(longitude), longitude < 0 ? "W" : "E");
    }
}
