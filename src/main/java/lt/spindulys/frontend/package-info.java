/**
 * What the front ends (the command line, the viewer and the bench) share with each other and no
 * library user needs: the one line a user is shown for a failure, the program's version and the
 * process's peak heap. Not exported.
 */
package lt.spindulys.frontend;
