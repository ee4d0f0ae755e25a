package io.github.jdem846.shadow;

/**
 * The step of a ray march. Either the article's radius interval (eq. 9: the hypotenuse of the two cell sizes, taken
 * along the 3-D ray, so the horizontal step is r_i·cos(elevation)), or a fixed fraction of a cell measured along the
 * ray's major grid axis (1 = the ray advances exactly one column or row per step, whichever it crosses faster).
 *
 * @param cells step in cells along the major axis; NaN means the article's radius interval
 */
public record StepSize(double cells) {

    /** The article's radius interval, eq. 9. */
    public static final StepSize ARTICLE = new StepSize(Double.NaN);
    /** One cell along the major axis. */
    public static final StepSize ONE_CELL = new StepSize(1);
    /** Half a cell. */
    public static final StepSize HALF_CELL = new StepSize(0.5);
    /** A quarter of a cell. */
    public static final StepSize QUARTER_CELL = new StepSize(0.25);
    /** An eighth of a cell: the step of the {@code exact} reference. */
    public static final StepSize EIGHTH_CELL = new StepSize(0.125);

    /**
     * Checks the range: NaN for the article's interval, else 1/64 to 64 cells.
     *
     * @param cells step in cells along the major axis; NaN means the article's radius interval
     */
    public StepSize {
        if (!Double.isNaN(cells) && !(cells >= 1.0 / 64 && cells <= 64)) {
            throw new IllegalArgumentException("ray step must be between 1/64 and 64 cells (or the article's radius"
                    + " interval), got " + cells);
        }
    }

    /**
     * A step of {@code cells} cells along the major axis, 1/64 to 64.
     *
     * @param cells the step in cells along the major axis
     * @return the step
     */
    public static StepSize ofCells(double cells) {
        return new StepSize(cells);
    }

    /**
     * True for the article's radius interval (eq. 9).
     *
     * @return whether the step follows the article's radius interval
     */
    public boolean isArticle() {
        return Double.isNaN(cells);
    }

    @Override
    public String toString() {
        return isArticle() ? "article (eq. 9)" : cells + " cell";
    }
}
