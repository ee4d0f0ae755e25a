package io.github.jdem846.io.esri;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.UtmZone;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The old ArcInfo projection file: lines of a keyword and a value ({@code Projection GEOGRAPHIC}, {@code Datum
 * NAD83}, {@code Units DD}, {@code Zunits METERS}, …), which USGS NED GridFloat tiles and other older ESRI grids
 * carry instead of WKT and which Apache SIS does not parse. Read as GDAL reads it
 * ({@code OGRSpatialReference::importFromESRI}) for geographic grids and UTM, datum (else spheroid, else the
 * {@code Parameters} semi-axes, else WGS 84) and linear unit (none: metre, {@code FEET}: US survey foot, a number:
 * that many units per metre); any other projection gives a projected CRS with only its unit and ellipsoid known, so
 * metric cell sizes are right but latitude and longitude are not available.
 */
final class ArcInfoPrj {

    private static final double US_SURVEY_FOOT = 1200.0 / 3937.0;

    /** A datum or spheroid name, the EPSG code of its geographic CRS, and its ellipsoid. */
    private record Geodetic(String name, int epsg, Ellipsoid ellipsoid) {
    }

    private static final Ellipsoid CLARKE_1866 = new Ellipsoid("Clarke 1866", 6378206.4, 294.978698213898);
    private static final Ellipsoid INTERNATIONAL_1924 = new Ellipsoid("International 1924", 6378388.0, 297.0);

    private static final Map<String, Geodetic> DATUMS = Map.of(
            "NAD83", new Geodetic("NAD83", 4269, Ellipsoid.GRS80),
            "WGS84", new Geodetic("WGS 84", 4326, Ellipsoid.WGS84),
            "NAD27", new Geodetic("NAD27", 4267, CLARKE_1866),
            "WGS72", new Geodetic("WGS 72", 4322, new Ellipsoid("WGS 72", 6378135.0, 298.26)),
            "EUR", new Geodetic("ED50", 4230, INTERNATIONAL_1924),
            "ED50", new Geodetic("ED50", 4230, INTERNATIONAL_1924),
            "GDA94", new Geodetic("GDA94", 4283, Ellipsoid.GRS80));

    private static final Map<String, Geodetic> SPHEROIDS = Map.ofEntries(
            Map.entry("INT1909", new Geodetic("Unknown datum based upon the International 1924 ellipsoid", 4022,
                    INTERNATIONAL_1924)),
            Map.entry("INTERNATIONAL1909", new Geodetic("Unknown datum based upon the International 1924"
                    + " ellipsoid", 4022, INTERNATIONAL_1924)),
            Map.entry("AIRY", new Geodetic("Unknown datum based upon the Airy 1830 ellipsoid", 4001,
                    new Ellipsoid("Airy 1830", 6377563.396, 299.3249646))),
            Map.entry("CLARKE1866", new Geodetic("Unknown datum based upon the Clarke 1866 ellipsoid", 4008,
                    CLARKE_1866)),
            Map.entry("GRS80", new Geodetic("Unknown datum based upon the GRS 1980 ellipsoid", 4019,
                    Ellipsoid.GRS80)),
            Map.entry("GRS1980", new Geodetic("Unknown datum based upon the GRS 1980 ellipsoid", 4019,
                    Ellipsoid.GRS80)),
            Map.entry("KRASOVSKY", new Geodetic("Unknown datum based upon the Krassowsky 1940 ellipsoid", 4024,
                    new Ellipsoid("Krassowsky 1940", 6378245.0, 298.3))),
            Map.entry("BESSEL", new Geodetic("Unknown datum based upon the Bessel 1841 ellipsoid", 4004,
                    new Ellipsoid("Bessel 1841", 6377397.155, 299.1528128))));

    private ArcInfoPrj() {
    }

    /** True when the text is in this format: its first keyword is {@code Projection}. */
    static boolean looksLikeOne(String text) {
        String first = text.strip();
        return first.regionMatches(true, 0, "Projection", 0, "Projection".length())
                && (first.length() == 10 || Character.isWhitespace(first.charAt(10)));
    }

    /**
     * The CRS the file describes.
     *
     * @param text    the file's content
     * @param file    the file's name, for notices
     * @param notices where to say how it was read and what is unknown
     * @throws IllegalArgumentException when it names no projection or an impossible UTM zone
     */
    static CrsInfo parse(String text, String file, List<String> notices) {
        Map<String, String> keys = new LinkedHashMap<>();
        for (String line : text.split("\\R")) {
            String[] kv = line.strip().split("\\s+", 2);
            if (!kv[0].isEmpty()) {
                keys.putIfAbsent(kv[0].toUpperCase(Locale.ROOT), kv.length > 1 ? kv[1].strip() : "");
            }
        }
        String projection = keys.getOrDefault("PROJECTION", "").toUpperCase(Locale.ROOT);
        if (projection.isEmpty()) {
            throw new IllegalArgumentException("the ArcInfo projection file names no Projection");
        }
        Geodetic geodetic = geodetic(keys, file, notices);
        verticalUnitNotice(keys.get("ZUNITS"), file, notices);
        if (projection.equals("GEOGRAPHIC")) {
            Integer epsg = geodetic.epsg() > 0 ? geodetic.epsg() : null;
            notices.add(file + " (ArcInfo projection file) read as geographic " + geodetic.name()
                    + (epsg != null ? " (EPSG:" + epsg + ")" : " on " + geodetic.ellipsoid().name()));
            return CrsInfo.geographic(geodetic.name(), epsg, geodetic.ellipsoid());
        }
        double unit = linearUnit(keys.getOrDefault("UNITS", ""));
        if (projection.equals("UTM")) {
            int zone = (int) number(keys.getOrDefault("ZONE", "0"));
            if (zone < 1 || zone > 60) {
                throw new IllegalArgumentException("the ArcInfo projection file's UTM Zone is '"
                        + keys.getOrDefault("ZONE", "") + "'; it must be 1 to 60");
            }
            double yShift = number(keys.getOrDefault("YSHIFT", "0"));
            boolean south = yShift == yShift && yShift != 0; // GDAL: a false northing means the south
            Optional<UtmZone> known = utmCode(geodetic, zone, south).flatMap(UtmZone::ofEpsg);
            CrsInfo crs = known.isPresent() && unit == 1.0 ? known.get().crsInfo()
                    : CrsInfo.projected(geodetic.name() + " / UTM zone " + zone + (south ? "S" : "N"),
                            unit == 1.0 ? utmCode(geodetic, zone, south).orElse(null) : null, unit,
                            geodetic.ellipsoid());
            notices.add(file + " (ArcInfo projection file) read as " + crs.name()
                    + (crs.epsg() != null ? " (EPSG:" + crs.epsg() + ")" : "") + unitNote(unit));
            return crs;
        }
        notices.add(file + " (ArcInfo projection file): projection " + projection + " read as a projected CRS"
                + unitNote(unit) + " on " + geodetic.ellipsoid().name() + "; its parameters are not read, so"
                + " latitude/longitude are unavailable");
        return CrsInfo.projected(geodetic.name() + " / " + projection, null, unit, geodetic.ellipsoid());
    }

    /** The datum, else the spheroid, else the semi-axes of {@code Parameters}, else WGS 84 (as GDAL). */
    private static Geodetic geodetic(Map<String, String> keys, String file, List<String> notices) {
        Geodetic datum = DATUMS.get(keys.getOrDefault("DATUM", "").toUpperCase(Locale.ROOT));
        if (datum != null) {
            return datum;
        }
        String spheroidName = keys.getOrDefault("SPHEROID", "").toUpperCase(Locale.ROOT);
        Geodetic spheroid = SPHEROIDS.get(spheroidName.equals("KRASSOVSKY") || spheroidName.equals("KRASSOWSKY")
                ? "KRASOVSKY" : spheroidName);
        if (spheroid != null) {
            return spheroid;
        }
        String[] axes = keys.getOrDefault("PARAMETERS", "").split("\\s+");
        if (axes.length == 2) {
            double a = number(axes[0]);
            double b = number(axes[1]);
            if (a > 0 && b > 0 && b <= a) {
                return new Geodetic("unknown", 0, new Ellipsoid("unknown", a, a == b ? Double.POSITIVE_INFINITY
                        : a / (a - b)));
            }
        }
        notices.add(file + " names no datum or spheroid known here (Datum '" + keys.getOrDefault("DATUM", "")
                + "', Spheroid '" + keys.getOrDefault("SPHEROID", "") + "'): WGS 84 assumed, as GDAL does");
        return DATUMS.get("WGS84");
    }

    /** The EPSG code of a UTM zone on a datum that has a family of them. */
    private static Optional<Integer> utmCode(Geodetic g, int zone, boolean south) {
        return switch (g.epsg()) {
            case 4326 -> Optional.of((south ? 32700 : 32600) + zone);
            case 4269 -> south ? Optional.empty() : Optional.of(26900 + zone);
            case 4267 -> south ? Optional.empty() : Optional.of(26700 + zone);
            default -> Optional.empty();
        };
    }

    /** Metres per unit: none → metre, FEET → US survey foot, a number → 1/number, any other word → metre. */
    private static double linearUnit(String units) {
        if (units.equalsIgnoreCase("FEET")) {
            return US_SURVEY_FOOT;
        }
        double perMetre = number(units);
        return perMetre > 0 ? 1.0 / perMetre : 1.0;
    }

    private static String unitNote(double unit) {
        return unit == 1.0 ? ", in metres" : String.format(Locale.ROOT, ", in units of %.10g m", unit);
    }

    /** Heights in another unit than metres: the hillshade needs them in the unit of the metric cell size. */
    private static void verticalUnitNotice(String zunits, String file, List<String> notices) {
        if (zunits == null) {
            return;
        }
        String z = zunits.toUpperCase(Locale.ROOT);
        if (z.equals("FEET")) {
            notices.add(file + " says the elevations are in feet (Zunits FEET): add --z-factor 0.3048 so that"
                    + " slopes and shadows use metres like the cell sizes");
        } else if (!z.isEmpty() && !z.equals("METERS") && !z.equals("METRES") && !z.equals("NO")) {
            notices.add(file + " gives the elevations' unit as '" + zunits + "'; they are used as metres");
        }
    }

    /** A decimal number, or NaN. */
    private static double number(String s) {
        try {
            return Double.parseDouble(s.strip());
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
