package io.github.jdem846.geo;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Recognises, without Apache SIS, the WKT 1 (ESRI or OGC) of the CRSs most DEMs use: geographic WGS 84, NAD83 and
 * ETRS89 in degrees, and the UTM zones of {@link UtmZone}'s families on them. Parsing a {@code .prj} with SIS costs about
 * 0.35 s of a one-shot command (docs/performance.md); these CRSs are then known by their EPSG code, and
 * {@link CrsResolver#complete} builds SIS's definition only where latitude and longitude are needed, as for a
 * GeoTIFF's codes. Every number is checked (ellipsoid, prime meridian, units, all five projection parameters);
 * anything else, or anything more, is left to SIS ({@code CommonCrsWktTest} compares with SIS's parse).
 */
final class CommonCrsWkt {

    private static final double DEGREE = 0.0174532925199433;

    private CommonCrsWkt() {
    }

    /** A WKT element: its keyword and its values (quoted text as String, numbers as Double, words, elements). */
    private record Element(String keyword, List<Object> values) {

        Optional<Element> child(String keyword) {
            return children(keyword).stream().findFirst();
        }

        List<Element> children(String keyword) {
            List<Element> out = new ArrayList<>();
            for (Object v : values) {
                if (v instanceof Element e && e.keyword.equalsIgnoreCase(keyword)) {
                    out.add(e);
                }
            }
            return out;
        }

        /** The i-th value when it is a number, else NaN. */
        double number(int i) {
            return i < values.size() && values.get(i) instanceof Double d ? d : Double.NaN;
        }

        /** The i-th value when it is quoted text, else "". */
        String text(int i) {
            return i < values.size() && values.get(i) instanceof String s ? s : "";
        }
    }

    /** The CRS when the WKT is one of those recognised, else empty (SIS then parses it). */
    static Optional<CrsInfo> recognize(String wkt) {
        Element root;
        try {
            Parser p = new Parser(wkt);
            root = p.element();
            if (!p.atEnd()) {
                return Optional.empty();
            }
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
        if (root.keyword.equalsIgnoreCase("GEOGCS")) {
            return geographicCode(root).map(code -> switch (code) {
                case 4326 -> CrsInfo.WGS84;
                case 4269 -> CrsInfo.geographic("NAD83", 4269, Ellipsoid.GRS80);
                default -> CrsInfo.geographic("ETRS89", 4258, Ellipsoid.GRS80);
            });
        }
        if (root.keyword.equalsIgnoreCase("PROJCS")) {
            return utm(root).map(UtmZone::crsInfo);
        }
        return Optional.empty();
    }

    /** 4326, 4269 or 4258 for a GEOGCS of WGS 84, NAD83 or ETRS89 in degrees from Greenwich, else empty. */
    private static Optional<Integer> geographicCode(Element geogcs) {
        Optional<Element> spheroid = geogcs.child("DATUM").flatMap(d -> d.child("SPHEROID"));
        Optional<Element> primem = geogcs.child("PRIMEM");
        Optional<Element> unit = geogcs.child("UNIT");
        if (spheroid.isEmpty() || primem.isEmpty() || unit.isEmpty() || primem.get().number(1) != 0
                || Math.abs(unit.get().number(1) - DEGREE) > 1e-15 || geogcs.children("DATUM").size() != 1) {
            return Optional.empty();
        }
        String datum = normalized(geogcs.child("DATUM").get().text(0));
        double a = spheroid.get().number(1);
        double invF = spheroid.get().number(2);
        if (a != 6378137.0) {
            return Optional.empty();
        }
        if ((datum.equals("WGS1984") || datum.equals("WGS84")) && invF == 298.257223563) {
            return Optional.of(4326);
        }
        if ((datum.equals("NORTHAMERICAN1983") || datum.equals("NORTHAMERICANDATUM1983") || datum.equals("NAD83"))
                && invF == 298.257222101) {
            return Optional.of(4269);
        }
        if ((datum.equals("ETRS1989") || datum.equals("EUROPEANTERRESTRIALREFERENCESYSTEM1989")
                || datum.equals("ETRS89")) && invF == 298.257222101) {
            return Optional.of(4258);
        }
        return Optional.empty();
    }

    /** The UTM zone a PROJCS is, when its base is recognised and every parameter is the zone's. */
    private static Optional<UtmZone> utm(Element projcs) {
        Optional<Integer> base = projcs.child("GEOGCS").flatMap(CommonCrsWkt::geographicCode);
        Optional<Element> projection = projcs.child("PROJECTION");
        Optional<Element> unit = projcs.child("UNIT");
        if (base.isEmpty() || projection.isEmpty() || unit.isEmpty() || unit.get().number(1) != 1.0
                || !normalized(projection.get().text(0)).equals("TRANSVERSEMERCATOR")) {
            return Optional.empty();
        }
        double k = Double.NaN;
        double falseEasting = Double.NaN;
        double falseNorthing = Double.NaN;
        double centralMeridian = Double.NaN;
        double originLatitude = Double.NaN;
        List<Element> parameters = projcs.children("PARAMETER");
        if (parameters.size() != 5) {
            return Optional.empty();
        }
        for (Element p : parameters) {
            double v = p.number(1);
            switch (normalized(p.text(0))) {
                case "SCALEFACTOR" -> k = v;
                case "FALSEEASTING" -> falseEasting = v;
                case "FALSENORTHING" -> falseNorthing = v;
                case "CENTRALMERIDIAN" -> centralMeridian = v;
                case "LATITUDEOFORIGIN" -> originLatitude = v;
                default -> {
                    return Optional.empty();
                }
            }
        }
        double zone = (centralMeridian + 183) / 6;
        if (k != UtmZone.CENTRAL_SCALE || falseEasting != UtmZone.FALSE_EASTING || originLatitude != 0
                || zone != Math.rint(zone) || zone < 1 || zone > 60
                || (falseNorthing != 0 && falseNorthing != 10_000_000)) {
            return Optional.empty();
        }
        boolean south = falseNorthing != 0;
        if (base.get() != 4326 && south) {
            return Optional.empty(); // NAD83's and ETRS89's zones are all northern
        }
        int family = switch (base.get()) {
            case 4326 -> south ? 32700 : 32600;
            case 4269 -> 26900;
            default -> 25800;
        };
        return UtmZone.ofEpsg(family + (int) zone); // empty outside the family's range of zones
    }

    /** Upper case without "D_" prefix, spaces, underscores and other punctuation: "D_WGS_1984" → "WGS1984". */
    private static String normalized(String name) {
        String n = name.toUpperCase(Locale.ROOT);
        if (n.startsWith("D_")) {
            n = n.substring(2);
        }
        return n.replaceAll("[^A-Z0-9]", "");
    }

    /** A recursive-descent reader of WKT 1: {@code KEYWORD[value, …]} with brackets or parentheses. */
    private static final class Parser {
        private final String s;
        private int at;

        Parser(String s) {
            this.s = s;
        }

        boolean atEnd() {
            skipBlanks();
            return at == s.length();
        }

        Element element() {
            String keyword = word();
            skipBlanks();
            if (at >= s.length() || (s.charAt(at) != '[' && s.charAt(at) != '(')) {
                throw new IllegalArgumentException("expected [ after " + keyword);
            }
            at++;
            List<Object> values = new ArrayList<>();
            while (true) {
                values.add(value());
                skipBlanks();
                if (at >= s.length()) {
                    throw new IllegalArgumentException("unclosed " + keyword);
                }
                char c = s.charAt(at++);
                if (c == ']' || c == ')') {
                    return new Element(keyword, values);
                }
                if (c != ',') {
                    throw new IllegalArgumentException("unexpected " + c);
                }
            }
        }

        private Object value() {
            skipBlanks();
            if (at >= s.length()) {
                throw new IllegalArgumentException("truncated");
            }
            char c = s.charAt(at);
            if (c == '"') {
                int end = s.indexOf('"', at + 1);
                if (end < 0) {
                    throw new IllegalArgumentException("unclosed quote");
                }
                String text = s.substring(at + 1, end);
                at = end + 1;
                return text;
            }
            if (c == '-' || c == '+' || c == '.' || Character.isDigit(c)) {
                int start = at;
                while (at < s.length() && "+-.eE0123456789".indexOf(s.charAt(at)) >= 0) {
                    at++;
                }
                try {
                    return Double.parseDouble(s.substring(start, at));
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("not a number: " + s.substring(start, at), e);
                }
            }
            int save = at;
            String w = word();
            skipBlanks();
            if (at < s.length() && (s.charAt(at) == '[' || s.charAt(at) == '(')) {
                at = save;
                return element();
            }
            return w; // a bare word such as EAST in AXIS["X",EAST]
        }

        private String word() {
            skipBlanks();
            int start = at;
            while (at < s.length() && (Character.isLetterOrDigit(s.charAt(at)) || s.charAt(at) == '_')) {
                at++;
            }
            if (start == at) {
                throw new IllegalArgumentException("expected a keyword at " + at);
            }
            return s.substring(start, at);
        }

        private void skipBlanks() {
            while (at < s.length() && Character.isWhitespace(s.charAt(at))) {
                at++;
            }
        }
    }
}
