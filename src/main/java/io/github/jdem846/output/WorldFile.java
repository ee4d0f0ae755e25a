package io.github.jdem846.output;

import java.math.BigDecimal;

/**
 * An ESRI world file: the six coefficients of the affine map from pixel (column, row) to world (x, y),
 * {@code x = A·col + B·row + C}, {@code y = D·col + E·row + F}, where (col, row) = (0, 0) is the <em>centre</em>
 * of the upper-left pixel. The file holds one number per line in the order A, D, B, E, C, F.
 *
 * @param a pixel width in x (east) per column
 * @param d rotation term: y change per column (0 for north-up images)
 * @param b rotation term: x change per row (0 for north-up images)
 * @param e pixel height in y per row; negative for north-up images
 * @param c x of the centre of the upper-left pixel
 * @param f y of the centre of the upper-left pixel
 */
record WorldFile(double a, double d, double b, double e, double c, double f) {

    /**
     * The world file of a north-up image of {@code width × height} pixels covering {@code geo}: A = extent x /
     * width, E = −extent y / height, C and F half a pixel inside the north-west corner.
     */
    public static WorldFile of(GeoReference geo, int width, int height) {
        double pixelWidth = geo.pixelWidth(width);
        double pixelHeight = geo.pixelHeight(height);
        return new WorldFile(pixelWidth, 0, 0, -pixelHeight, geo.westX() + pixelWidth / 2,
                geo.northY() - pixelHeight / 2);
    }

    /**
     * The six lines A, D, B, E, C, F. Each number is the shortest decimal that reads back as the same double,
     * written without an exponent.
     */
    public String toText() {
        StringBuilder sb = new StringBuilder();
        for (double v : new double[]{a, d, b, e, c, f}) {
            sb.append(plain(v)).append('\n');
        }
        return sb.toString();
    }

    private static String plain(double v) {
        if (v == 0) {
            return "0.0"; // also for −0.0
        }
        String s = new BigDecimal(Double.toString(v)).toPlainString();
        return s.contains(".") ? s : s + ".0";
    }
}
